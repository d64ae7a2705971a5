// Strategies given on the command line, "wach:mu=0.4,limit=gir" or as a JSON object, validated by the
// same rules as the case file; errors name the option ("--strategy[1].mu").
#pragma once

#include <string>

#include "impact3d/case_format/case_spec.hpp"

namespace impact3d::case_format {

StrategySpec read_strategy_option(const std::string& text, int index);

}  // namespace impact3d::case_format
