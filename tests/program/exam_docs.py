"""The front pages and the manual against the program: every command of a ```sh block in README.md and
docs/*.md that runs the program runs, from a scratch directory holding the repository's examples/ and
verification/, and exits 0 with something on standard output; every relative link and anchor resolves;
README.md stays a front page (at most 250 lines) and BENCHMARKS.md at most 400.

Where the expected answers come from: the pages themselves (what they tell a reader to type) and the
limits issue 58 set for the front pages.

Usage: python3 exam_docs.py SOURCE_DIR IMPACT3D_PROGRAM
"""
import os
import re
import shlex
import subprocess
import sys
import tempfile

PROGRAM_PREFIXES = ("build/cli/impact3d ", "impact3d ")
# Lines a block may hold that this test does not run, each run by another check: the README's two
# commands (CI runs (b) itself; (a) is (b)'s first part) and the regeneration (the codegen drift test).
OTHER_PREFIXES = ("bash .ci/install-deps", "cmake ", "#")


def slug(heading):
    """GitHub's anchor of a heading: lower case, punctuation but '-' and '_' dropped, spaces to '-'."""
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def anchors(text):
    return {slug(m.group(1)) for m in re.finditer(r"^#+ (.*)$", text, re.M)}


def main():
    source, program = sys.argv[1], sys.argv[2]
    pages = ["README.md"] + sorted("docs/" + f for f in os.listdir(os.path.join(source, "docs")) if f.endswith(".md"))
    texts = {p: open(os.path.join(source, p), encoding="utf-8").read() for p in pages}
    failures = []

    for page, limit in (("README.md", 250), ("BENCHMARKS.md", 400)):
        lines = open(os.path.join(source, page), encoding="utf-8").read().count("\n")
        if lines > limit:
            failures.append(f"{page}: {lines} lines, more than the {limit} a front page holds")

    links = 0
    for page, text in texts.items():
        for m in re.finditer(r"\]\(([^)\s]+)\)", text):
            target = m.group(1)
            if re.match(r"[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            resolved = os.path.normpath(os.path.join(source, os.path.dirname(page), path)) if path else os.path.join(source, page)
            links += 1
            if not os.path.exists(resolved):
                failures.append(f"{page}: link to {target}: no such file")
            elif anchor and resolved.endswith(".md"):
                if anchor not in anchors(open(resolved, encoding="utf-8").read()):
                    failures.append(f"{page}: link to {target}: no such heading")

    commands = []
    for page, text in texts.items():
        for block in re.findall(r"```sh\n(.*?)```", text, re.S):
            for line in block.splitlines():
                line = line.split("  #")[0].strip()
                if not line:
                    continue
                if line.startswith(PROGRAM_PREFIXES):
                    commands.append((page, line))
                elif not line.startswith(OTHER_PREFIXES):
                    failures.append(f"{page}: a sh block's line this test neither runs nor knows: {line}")

    with tempfile.TemporaryDirectory() as scratch:
        for d in ("examples", "verification"):
            os.symlink(os.path.join(source, d), os.path.join(scratch, d))
        for page, line in commands:
            words = shlex.split(line)
            argv = [program] + words[1:]
            try:
                run = subprocess.run(argv, cwd=scratch, capture_output=True, timeout=600)
            except subprocess.TimeoutExpired:
                failures.append(f"{page}: `{line}` took more than 600 s")
                continue
            if run.returncode != 0:
                err = run.stderr.decode(errors="replace").strip().splitlines()
                failures.append(f"{page}: `{line}` exited {run.returncode}: {err[-1] if err else ''}")
            elif not run.stdout.strip() and "-o" not in words:
                failures.append(f"{page}: `{line}` printed nothing")

    print(f"{len(commands)} commands run, {links} links followed, {len(pages)} pages read")
    for f in failures:
        print("FAIL", f)
    # A check that ran nothing fails: the README's tour alone holds nine commands.
    if len(commands) < 9 or links < 20:
        print(f"FAIL: only {len(commands)} commands and {links} links found")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
