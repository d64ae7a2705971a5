// impact3d.montecarlo and impact3d.sensitivity: the contract's documents (many-cases.md), and for a
// Monte Carlo run, when asked, every sample as NumPy arrays.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "case.hpp"

namespace impact3d::python {

struct Uncertainty {
  std::string text;    // the uncertainty file's JSON
  std::string source;  // its file, named first in messages; empty for a dict
};

// (the JSON document, the samples or None). `samples` overrides the file's count and `seed` its seed.
pybind11::tuple montecarlo(const Case& c, const Uncertainty& u, const std::vector<std::string>& strategies,
                           const std::string& precision, const std::string& engine, unsigned jobs,
                           std::optional<std::uint64_t> samples, std::optional<std::uint64_t> seed, bool keep);

std::string sensitivity_json(const Case& c, const std::vector<std::string>& strategies, const std::string& engine);

}  // namespace impact3d::python
