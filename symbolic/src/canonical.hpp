// A canonical form of GiNaC expressions for printing. GiNaC orders the operands of sums and products by
// hash, and its hashes include addresses that change from run to run; with the order it also changes
// which of A and -A it keeps for a sum inside a product. Here every sum and product sorts its operands
// by canonical text, every sum is scaled so that its first term (in that order, signs ignored) is
// positive, the sign moving out to the enclosing product, and equal subexpressions are one node. The
// printed output is then a function of the mathematics alone.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace impact3d::symbolic {

struct Node {
  enum class Kind { number, symbol, add, mul, power, function } kind;
  GiNaC::numeric value;    // number; exponent of a power
  std::string name;        // symbol or function name
  std::vector<int> args;   // operands; sorted by key for add and mul
  std::string key;         // canonical text
};

class Dag {
 public:
  int intern(const GiNaC::ex& e);
  const Node& operator[](int id) const { return nodes_[id]; }
  std::size_t size() const { return nodes_.size(); }

 private:
  int add_node(Node n);
  // (coefficient, monic node); node -1 stands for the number 1.
  std::pair<GiNaC::numeric, int> split(const GiNaC::ex& e);
  int number(const GiNaC::numeric& v);
  int join(const GiNaC::numeric& c, int node);  // c * node as one node
  int product(const std::vector<int>& factors);  // monic product node (factors already monic, sorted here)
  std::vector<Node> nodes_;
  std::map<std::string, int> by_key_;
};

}  // namespace impact3d::symbolic
