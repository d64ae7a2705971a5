// The figures of `impact3d plot`, each drawn from a FigureContext (figure.hpp).
#pragma once

#include <cstddef>

#include "impact3d/cli/figures/figure.hpp"

namespace impact3d::cli {

void contact_plane_view(FigureContext& c);                // plane_views.cpp
void solution_plane_view(FigureContext& c, std::size_t k);  // plane_views.cpp
void impulse_space_view(FigureContext& c);                // space_view.cpp
void sweeps(FigureContext& c);                            // sweeps.cpp
void collision_view(FigureContext& c, std::size_t k);     // collision_view.cpp
void stronge_views(FigureContext& c, std::size_t k);      // stronge_views.cpp: when k is stronge

}  // namespace impact3d::cli
