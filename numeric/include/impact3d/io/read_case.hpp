// Everything a program needs to read a case file and write the contract's result.
#pragma once

#include "impact3d/io/case_spec.hpp"
#include "impact3d/io/result_json.hpp"
#include "impact3d/io/strategy_option.hpp"
#include "impact3d/io/to_scene.hpp"
