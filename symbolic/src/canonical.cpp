#include "canonical.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace impact3d::symbolic {

using namespace GiNaC;

namespace {

std::string numeric_text(const numeric& n) {
  if (!n.is_rational()) throw std::runtime_error("canonical form: non-rational number");
  std::ostringstream os;
  os << n;
  return os.str();
}

}  // namespace

int Dag::add_node(Node n) {
  auto it = by_key_.find(n.key);
  if (it != by_key_.end()) return it->second;
  nodes_.push_back(std::move(n));
  const int id = static_cast<int>(nodes_.size()) - 1;
  by_key_.emplace(nodes_.back().key, id);
  return id;
}

int Dag::number(const numeric& v) {
  Node n;
  n.kind = Node::Kind::number;
  n.value = v;
  // Built up in a new string, not "#" + a temporary nor "#" assigned: GCC 12's false -Wrestrict (PR 105329).
  const std::string text = numeric_text(v);
  std::string key(1, '#');
  key += text;
  n.key = std::move(key);
  return add_node(std::move(n));
}

int Dag::product(const std::vector<int>& factors_in) {
  std::vector<int> factors = factors_in;
  std::sort(factors.begin(), factors.end(), [&](int a, int b) { return nodes_[a].key < nodes_[b].key; });
  if (factors.size() == 1) return factors[0];
  Node n;
  n.kind = Node::Kind::mul;
  n.args = factors;
  std::string k = "*(";
  for (std::size_t i = 0; i < factors.size(); ++i) k += (i ? "," : "") + nodes_[factors[i]].key;
  n.key = k + ")";
  return add_node(std::move(n));
}

int Dag::join(const numeric& c, int node) {
  if (node < 0) return number(c);
  if (c == 1) return node;
  std::vector<int> factors{number(c)};
  if (nodes_[node].kind == Node::Kind::mul) {
    factors.insert(factors.end(), nodes_[node].args.begin(), nodes_[node].args.end());
  } else {
    factors.push_back(node);
  }
  // The number's key sorts first ('#'), so this is the canonical product with a coefficient.
  return product(factors);
}

std::pair<numeric, int> Dag::split(const ex& e) {
  if (is_a<numeric>(e)) return {ex_to<numeric>(e), -1};
  if (is_a<symbol>(e)) {
    Node n;
    n.kind = Node::Kind::symbol;
    n.name = ex_to<symbol>(e).get_name();
    n.key = n.name;
    return {1, add_node(std::move(n))};
  }
  if (is_a<power>(e)) {
    if (!is_a<numeric>(e.op(1))) throw std::runtime_error("canonical form: symbolic exponent");
    const numeric k = ex_to<numeric>(e.op(1));
    auto [c, base] = split(e.op(0));
    numeric coef = 1;
    int b = base;
    if (k.is_integer()) {
      coef = pow(c, k);  // (c n)^k = c^k n^k
    } else {
      b = join(c, base);  // a root keeps its base whole
    }
    if (b < 0) throw std::runtime_error("canonical form: power of a number");
    Node n;
    n.kind = Node::Kind::power;
    n.value = k;
    n.args = {b};
    n.key = "(" + nodes_[b].key + ")^" + numeric_text(k);
    return {coef, add_node(std::move(n))};
  }
  if (is_a<mul>(e)) {
    numeric coef = 1;
    std::vector<int> factors;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      auto [c, f] = split(e.op(i));
      coef *= c;
      if (f < 0) continue;
      if (nodes_[f].kind == Node::Kind::mul) factors.insert(factors.end(), nodes_[f].args.begin(), nodes_[f].args.end());
      else factors.push_back(f);
    }
    if (factors.empty()) return {coef, -1};
    return {coef, product(factors)};
  }
  if (is_a<add>(e)) {
    std::vector<std::pair<numeric, int>> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(split(e.op(i)));
    auto key = [&](int node) { return node < 0 ? std::string("#1") : nodes_[node].key; };
    std::sort(terms.begin(), terms.end(), [&](const auto& a, const auto& b) { return key(a.second) < key(b.second); });
    const numeric sign = terms.front().first < 0 ? numeric(-1) : numeric(1);
    Node n;
    n.kind = Node::Kind::add;
    for (const auto& [c, t] : terms) n.args.push_back(join(sign * c, t));
    std::string k = "+(";
    for (std::size_t i = 0; i < n.args.size(); ++i) k += (i ? "," : "") + nodes_[n.args[i]].key;
    n.key = k + ")";
    return {sign, add_node(std::move(n))};
  }
  if (is_a<function>(e)) {
    Node n;
    n.kind = Node::Kind::function;
    n.name = ex_to<function>(e).get_name();
    for (std::size_t i = 0; i < e.nops(); ++i) n.args.push_back(intern(e.op(i)));
    std::string k = n.name + "(";
    for (std::size_t i = 0; i < n.args.size(); ++i) k += (i ? "," : "") + nodes_[n.args[i]].key;
    n.key = k + ")";
    return {1, add_node(std::move(n))};
  }
  throw std::runtime_error("canonical form: unsupported expression");
}

int Dag::intern(const ex& e) {
  auto [c, node] = split(e);
  return join(c, node);
}

}  // namespace impact3d::symbolic
