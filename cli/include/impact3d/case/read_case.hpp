// Everything a program needs to read a case file and write the contract's result.
#pragma once

#include "impact3d/case/case_spec.hpp"
#include "impact3d/case/result_json.hpp"
#include "impact3d/case/strategy_option.hpp"
#include "impact3d/case/to_scene.hpp"
