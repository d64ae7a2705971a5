// Everything a program needs to read a case file and write the contract's result.
#pragma once

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/result_json.hpp"
#include "impact3d/case_format/strategy_option.hpp"
#include "impact3d/case_format/to_scene.hpp"
