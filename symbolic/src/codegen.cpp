#include "codegen.hpp"

#include <algorithm>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "canonical.hpp"

namespace impact3d::symbolic {

using namespace GiNaC;

namespace {

std::string integer_text(const numeric& n) {
  std::ostringstream os;
  os << n;
  return os.str();
}

struct Printed {
  bool negative = false;
  std::string text;
  bool atomic = false;  // usable as an operand of * and / without parentheses
};

class CodePrinter {
 public:
  CodePrinter(const Dag& dag, const std::map<std::string, std::string>& symbols) : dag_(dag), symbols_(symbols) {}

  std::map<int, std::string> hoisted;  // node -> temporary name, once emitted
  std::set<int> to_hoist;
  std::set<std::string> functions;
  long ops = 0;

  std::string expression(int id) { return signed_text(print(id, true)); }

  // Operand of a product or quotient.
  std::string atom(int id) {
    Printed p = print(id, true);
    if (p.negative) return "(-" + p.text + ")";
    return p.atomic ? p.text : "(" + p.text + ")";
  }

  Printed print(int id, bool use_names) {
    if (use_names) {
      auto it = hoisted.find(id);
      if (it != hoisted.end()) return {false, it->second, true};
    }
    const Node& n = dag_[id];
    switch (n.kind) {
      case Node::Kind::number: return constant(n.value);
      case Node::Kind::symbol: {
        auto it = symbols_.find(n.name);
        if (it == symbols_.end()) throw std::runtime_error("kernel: no C++ for symbol " + n.name);
        return {false, it->second, true};
      }
      case Node::Kind::function: {
        functions.insert(n.name);
        ++ops;
        std::string s = n.name + "(";
        for (std::size_t i = 0; i < n.args.size(); ++i) s += (i ? ", " : "") + expression(n.args[i]);
        return {false, s + ")", true};
      }
      case Node::Kind::power: return power(n);
      case Node::Kind::mul: return product(n);
      case Node::Kind::add: return sum(n);
    }
    throw std::runtime_error("kernel: unknown node");
  }

 private:
  const Dag& dag_;
  const std::map<std::string, std::string>& symbols_;

  static std::string signed_text(const Printed& p) { return p.negative ? "-" + p.text : p.text; }

  static Printed constant(const numeric& v) {
    const numeric a = abs(v);
    if (a.is_integer()) return {v < 0, "Scalar(" + integer_text(a) + ")", true};
    return {v < 0, "(Scalar(" + integer_text(a.numer()) + ") / Scalar(" + integer_text(a.denom()) + "))", true};
  }

  Printed power(const Node& n) {
    const numeric& e = n.value;
    const int base = n.args[0];
    if (e == numeric(1, 2)) {
      functions.insert("sqrt");
      ++ops;
      return {false, "sqrt(" + expression(base) + ")", true};
    }
    if (e == numeric(-1, 2)) {
      functions.insert("sqrt");
      ops += 2;
      return {false, "Scalar(1) / sqrt(" + expression(base) + ")", false};
    }
    if (!e.is_integer()) {
      functions.insert("pow");
      ++ops;
      return {false, "pow(" + expression(base) + ", " + signed_text(constant(e)) + ")", true};
    }
    const long k = std::abs(e.to_long());
    std::string s = atom(base);
    for (long i = 1; i < k; ++i) s += " * " + atom(base);
    ops += k - 1;
    if (e > 0) return {false, s, k == 1};
    ++ops;
    return {false, "Scalar(1) / " + (k == 1 ? s : "(" + s + ")"), false};
  }

  Printed product(const Node& n) {
    numeric coef = 1;
    std::vector<std::string> num, den;
    for (int a : n.args) {
      const Node& f = dag_[a];
      if (f.kind == Node::Kind::number) {
        coef *= f.value;
      } else if (f.kind == Node::Kind::power && f.value.is_integer() && f.value < 0 && !hoisted.count(a)) {
        const long k = -f.value.to_long();
        for (long i = 0; i < k; ++i) den.push_back(atom(f.args[0]));
      } else {
        num.push_back(atom(a));
      }
    }
    const bool negative = coef < 0;
    coef = abs(coef);
    if (coef.numer() != 1) num.insert(num.begin(), "Scalar(" + integer_text(coef.numer()) + ")");
    if (coef.denom() != 1) den.insert(den.begin(), "Scalar(" + integer_text(coef.denom()) + ")");
    if (num.empty()) num.push_back("Scalar(1)");
    std::string s = num[0];
    for (std::size_t i = 1; i < num.size(); ++i) s += " * " + num[i];
    ops += static_cast<long>(num.size()) - 1;
    if (!den.empty()) {
      std::string d = den[0];
      for (std::size_t i = 1; i < den.size(); ++i) d += " * " + den[i];
      ops += static_cast<long>(den.size());
      s += " / " + (den.size() == 1 ? d : "(" + d + ")");
    }
    return {negative, s, num.size() == 1 && den.empty()};
  }

  Printed sum(const Node& n) {
    std::string s;
    bool first_negative = false;
    for (std::size_t i = 0; i < n.args.size(); ++i) {
      Printed t = print(n.args[i], true);
      if (i == 0) {
        first_negative = t.negative;
        s = t.text;
      } else {
        s += (t.negative ? " - " : " + ") + t.text;
      }
    }
    ops += static_cast<long>(n.args.size()) - 1;
    if (first_negative) {
      ++ops;
      s = "-" + s;
    }
    return {false, s, false};
  }
};

// Nodes worth a temporary: used by two or more parents (or outputs), or the compound base of a power.
std::set<int> choose_hoisted(const Dag& dag, const std::vector<int>& roots) {
  std::map<int, int> uses;
  std::set<int> seen;
  std::set<int> hoist;
  std::vector<int> stack(roots.rbegin(), roots.rend());
  for (int r : roots) ++uses[r];
  while (!stack.empty()) {
    const int id = stack.back();
    stack.pop_back();
    if (!seen.insert(id).second) continue;
    const Node& n = dag[id];
    std::set<int> distinct(n.args.begin(), n.args.end());
    for (int a : distinct) {
      ++uses[a];
      stack.push_back(a);
    }
    if (n.kind == Node::Kind::power && n.value.is_integer() && std::abs(n.value.to_long()) >= 2) {
      const Node& b = dag[n.args[0]];
      if (b.kind != Node::Kind::symbol && b.kind != Node::Kind::number) hoist.insert(n.args[0]);
    }
  }
  for (const auto& [id, count] : uses) {
    const Node& n = dag[id];
    const bool compound = n.kind != Node::Kind::symbol && n.kind != Node::Kind::number;
    if (compound && count >= 2) hoist.insert(id);
  }
  return hoist;
}

}  // namespace

namespace {

constexpr std::size_t kDocWidth = 100;   // docstrings and signatures
constexpr std::size_t kCodeWidth = 120;  // statements, where a break exists

// `text` filled into lines of at most kDocWidth columns, the first after `first`, the rest after `rest`.
std::string wrap_words(const std::string& text, const std::string& first, const std::string& rest) {
  std::istringstream words(text);
  std::string out, line = first, word;
  bool empty = true;
  while (words >> word) {
    if (!empty && line.size() + 1 + word.size() > kDocWidth) {
      out += line + "\n";
      line = rest;
      empty = true;
    }
    line += (empty ? "" : " ") + word;
    empty = false;
  }
  return out + line + "\n";
}

// One statement (without indentation) as lines of at most kCodeWidth columns where it can be broken:
// after a binary operator, preferring in the second half of the line the shallowest parenthesis depth,
// then + and - over * and /, then the last. Continuation lines are indented 4 more; only blanks change,
// never a token or its order.
std::string wrap_statement(const std::string& stmt, std::size_t indent) {
  struct Break {
    std::size_t pos;  // the blank after the operator
    int rank;         // 2 * parenthesis depth, + 1 for * and /
  };
  std::vector<Break> breaks;
  int depth = 0;
  for (std::size_t i = 0; i + 2 < stmt.size(); ++i) {
    const char c = stmt[i];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (c == ' ' && std::string("+-*/").find(stmt[i + 1]) != std::string::npos && stmt[i + 2] == ' ')
      breaks.push_back({i + 2, 2 * depth + (stmt[i + 1] == '*' || stmt[i + 1] == '/' ? 1 : 0)});
  }
  std::string out;
  std::size_t start = 0, pad = indent;
  std::size_t b = 0;  // first break after start
  while (pad + stmt.size() - start > kCodeWidth) {
    while (b < breaks.size() && breaks[b].pos <= start) ++b;
    if (b == breaks.size()) break;
    std::size_t pick = b;
    if (pad + breaks[b].pos - start <= kCodeWidth) {
      // Fitting breaks; among those in the second half of the line, the lowest rank, then the last.
      std::size_t last = b;
      while (last + 1 < breaks.size() && pad + breaks[last + 1].pos - start <= kCodeWidth) ++last;
      const std::size_t half = pad + (kCodeWidth - pad) / 2;
      std::size_t from = b;
      while (from < last && pad + breaks[from].pos - start < half) ++from;
      pick = last;
      for (std::size_t k = last + 1; k-- > from;)
        if (breaks[k].rank < breaks[pick].rank) pick = k;
    }
    out += std::string(pad, ' ') + stmt.substr(start, breaks[pick].pos - start) + "\n";
    start = breaks[pick].pos + 1;
    pad = indent + 4;
  }
  return out + std::string(pad, ' ') + stmt.substr(start) + "\n";
}

}  // namespace

std::string shape_of(const std::string& type) {
  const std::string eigen = "Eigen::Matrix<Scalar, ";
  const std::size_t at = type.find(eigen);
  if (at == std::string::npos) return "scalar";
  const std::size_t comma = type.find(", ", at + eigen.size());
  const std::size_t close = type.find('>', comma);
  return type.substr(at + eigen.size(), comma - at - eigen.size()) + "x" + type.substr(comma + 2, close - comma - 2);
}

PrintedKernel print_kernel(const Kernel& k) {
  Dag dag;
  std::vector<int> roots;
  for (const auto& [name, e] : k.locals) roots.push_back(dag.intern(e));
  for (const auto& [lhs, e] : k.outputs) roots.push_back(dag.intern(e));
  CodePrinter p(dag, k.symbol_code);
  p.to_hoist = choose_hoisted(dag, roots);

  PrintedKernel r;
  std::string intermediate;
  int next = 0;
  // Post-order: a temporary is defined after every temporary it uses.
  std::function<void(int)> emit = [&](int id) {
    if (p.hoisted.count(id)) return;
    for (int a : dag[id].args) emit(a);
    if (p.to_hoist.count(id)) {
      const std::string text = p.expression(id);
      const std::string name = "t" + std::to_string(next++);
      intermediate += wrap_statement("const Scalar " + name + " = " + text + ";", 2);
      ++r.intermediate_terms;
      p.hoisted.emplace(id, name);
    }
  };
  std::string assigns;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    emit(roots[i]);
    if (i < k.locals.size()) {
      intermediate += wrap_statement("const Scalar " + k.locals[i].first + " = " + p.expression(roots[i]) + ";", 2);
      ++r.intermediate_terms;
    } else {
      assigns += wrap_statement(k.outputs[i - k.locals.size()].first + " = " + p.expression(roots[i]) + ";", 2);
      ++r.output_terms;
    }
  }
  r.operations = p.ops;
  r.calls = p.functions;

  std::string s = wrap_words(k.doc, "/// ", "/// ") + "///\n/// Args:\n";
  for (const auto& a : k.args) {
    const std::string name = a.decl.substr(a.decl.rfind(' ') + 1);
    s += wrap_words(name + " (" + shape_of(a.decl) + "): " + a.doc, "///   ", "///       ");
  }
  s += wrap_words("Returns (" + shape_of(k.returns) + "): " + k.returns_doc, "/// ", "///     ");
  s += "/// Operations: " + std::to_string(p.ops) + " (additions, multiplications, divisions and calls)\n";

  // One parameter a line, aligned after the parenthesis when the longest fits in kDocWidth.
  s += "template <typename Scalar>\n";
  const std::string head = k.returns + " " + k.name + "(";
  std::size_t longest = 0;
  for (const auto& a : k.args) longest = std::max(longest, a.decl.size());
  const bool aligned = head.size() + longest + 2 <= kDocWidth;
  s += aligned ? head : head + "\n";
  for (std::size_t i = 0; i < k.args.size(); ++i) {
    if (i > 0 || !aligned) s += std::string(aligned ? head.size() : 4, ' ');
    s += k.args[i].decl + (i + 1 < k.args.size() ? ",\n" : ") {\n");
  }
  for (const auto& f : p.functions) s += "  using std::" + f + ";\n";
  if (!p.functions.empty()) s += "\n";
  s += "  // Intermediate terms (" + std::to_string(r.intermediate_terms) + ")\n" + intermediate + "\n";
  s += "  // Output terms (" + std::to_string(r.output_terms) + ")\n";
  s += "  " + k.returns + " out;\n" + assigns + "  return out;\n}\n";
  r.text = s;
  return r;
}

namespace {

class LatexPrinter {
 public:
  LatexPrinter(const Dag& dag, const std::map<std::string, std::string>& names) : dag_(dag), names_(names) {}

  std::string print(int id, int prec = 0) {
    const Node& n = dag_[id];
    switch (n.kind) {
      case Node::Kind::number: {
        const numeric a = abs(n.value);
        std::string s = a.is_integer() ? integer_text(a) : "\\frac{" + integer_text(a.numer()) + "}{" + integer_text(a.denom()) + "}";
        return n.value < 0 ? wrap("-" + s, prec > 0) : s;
      }
      case Node::Kind::symbol: {
        auto it = names_.find(n.name);
        return it == names_.end() ? n.name : it->second;
      }
      case Node::Kind::function: {
        std::string s = "\\" + n.name + "\\left(";
        for (std::size_t i = 0; i < n.args.size(); ++i) s += (i ? ", " : "") + print(n.args[i]);
        return s + "\\right)";
      }
      case Node::Kind::power: {
        if (n.value == numeric(1, 2)) return "\\sqrt{" + print(n.args[0]) + "}";
        if (n.value < 0) return "\\frac{1}{" + print_power(n.args[0], -n.value) + "}";
        return print_power(n.args[0], n.value);
      }
      case Node::Kind::mul: return wrap(product(n), prec > 1);
      case Node::Kind::add: {
        std::string s;
        for (std::size_t i = 0; i < n.args.size(); ++i) {
          std::string t = print(n.args[i], 1);
          const bool neg = !t.empty() && t[0] == '-';
          if (i == 0) s = t;
          else s += neg ? " - " + t.substr(1) : " + " + t;
        }
        return wrap(s, prec > 0);
      }
    }
    return "?";
  }

 private:
  const Dag& dag_;
  const std::map<std::string, std::string>& names_;

  static std::string wrap(const std::string& s, bool yes) { return yes ? "\\left(" + s + "\\right)" : s; }

  std::string print_power(int base, const numeric& e) {
    const std::string b = print(base, 2);
    if (e == 1) return b;
    if (e == numeric(1, 2)) return "\\sqrt{" + print(base) + "}";
    return "{" + b + "}^{" + integer_text(e) + "}";
  }

  std::string product(const Node& n) {
    numeric coef = 1;
    std::vector<std::string> num, den;
    for (int a : n.args) {
      const Node& f = dag_[a];
      if (f.kind == Node::Kind::number) coef *= f.value;
      else if (f.kind == Node::Kind::power && f.value < 0) den.push_back(print_power(f.args[0], -f.value));
      else num.push_back(print(a, 2));
    }
    const bool neg = coef < 0;
    coef = abs(coef);
    std::string top, bottom;
    for (const auto& s : num) top += (top.empty() ? "" : " ") + s;
    for (const auto& s : den) bottom += (bottom.empty() ? "" : " ") + s;
    if (coef.numer() != 1) top = integer_text(coef.numer()) + (top.empty() ? "" : " " + top);
    if (coef.denom() != 1) bottom = integer_text(coef.denom()) + (bottom.empty() ? "" : " " + bottom);
    if (top.empty()) top = "1";
    const std::string s = bottom.empty() ? top : "\\frac{" + top + "}{" + bottom + "}";
    return neg ? "-" + s : s;
  }
};

}  // namespace

std::string latex(const ex& e, const std::map<std::string, std::string>& names) {
  Dag dag;
  const int root = dag.intern(e);
  return LatexPrinter(dag, names).print(root);
}

}  // namespace impact3d::symbolic
