// A digest of what a figure draws, its titles aside: two figures with equal
// digests draw the same shapes, legends and views (a sweep says when its
// variants draw the same, whatever their titles, sweep/sweep.cpp).
#pragma once

#include <cstdint>

#include "render/figure.hpp"

namespace pita::render {

std::uint64_t figure_digest(const Figure& figure);

}  // namespace pita::render
