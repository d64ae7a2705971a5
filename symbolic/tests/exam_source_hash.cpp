// Exact answers of the inputs hash: SHA-256 test vectors, and what code_only keeps and drops.
#include <catch2/catch.hpp>

#include <string>

#include "source_hash.hpp"

using impact3d::symbolic::code_only;
using impact3d::symbolic::sha256_hex;

TEST_CASE("SHA-256 of the FIPS 180-4 test vectors", "[exam]") {
  CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(sha256_hex(std::string(1000000, 'a')) == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("code_only drops comments, blank lines and repeated blanks", "[exam]") {
  CHECK(code_only("int a;  // the a\n\n   int b; /* the b */\n") == "int a;\nint b;\n");
  CHECK(code_only("/* first\n   second */\nint   a =\t1;   \n") == "int a = 1;\n");
  CHECK(code_only("f(a, /* inline */ b);") == "f(a, b);\n");
  CHECK(code_only("x = a /**/ / b; // x\n") == "x = a / b;\n");
  CHECK(code_only("// only a comment\n\n") == "");
}

TEST_CASE("code_only keeps string, character and raw string literals verbatim", "[exam]") {
  CHECK(code_only("s = \"/// \" + t;  // doc\n") == "s = \"/// \" + t;\n");
  CHECK(code_only("s = \"a /* b */   c\";\n") == "s = \"a /* b */   c\";\n");
  CHECK(code_only("s = \"say \\\"//\\\"\"; // c\n") == "s = \"say \\\"//\\\"\";\n");
  CHECK(code_only("c = '\"'; d = '/'; // c\n") == "c = '\"'; d = '/';\n");
  CHECK(code_only("c = '\\''; s = \"//\";\n") == "c = '\\''; s = \"//\";\n");
  CHECK(code_only("s = R\"x(a // b\n  )\" c)x\"; // d\n") == "s = R\"x(a // b\n  )\" c)x\";\n");
  CHECK(code_only("s = u8\"//\"; w = L'/';\n") == "s = u8\"//\"; w = L'/';\n");
}

TEST_CASE("code_only reads digit separators as part of a number", "[exam]") {
  CHECK(code_only("n = 1'000'000; s = \"//\"; // c\n") == "n = 1'000'000; s = \"//\";\n");
  CHECK(code_only("x = 1.5e-3 + 0x1p+2;  // c\n") == "x = 1.5e-3 + 0x1p+2;\n");
}

TEST_CASE("code_only tells code from comments: a change to either side", "[exam]") {
  CHECK(code_only("a = 1;") != code_only("a = 2;"));
  CHECK(code_only("s = \"// a\";") != code_only("s = \"// b\";"));
  CHECK(code_only("a = 1; // one") == code_only("a = 1; /* uno */"));
}
