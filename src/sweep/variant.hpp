// A variant of a sweep: the base scene's JSON with each axis's value set at
// its pointer, as the text a user would have written by hand, and its content
// hash (what a resumed sweep compares).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sweep/grid.hpp"

namespace pita::sweep {

// The base scene as JSON, members in the file's order.
struct BaseScene {
  std::string path;  // as given; variants are read as if they were this file
  Json document;
};

// Reads and validates the base scene (throws scene::SceneError: exit 2) and
// checks every axis's pointer against it (throws SweepUsageError). A pointer
// must name a member or element of the scene, or a member that does not exist
// yet inside objects that do or can (`/timing/ease` on a scene without
// "timing"); the scene reader then refuses it in the first variant when the
// scene may not have that field. An array element must exist. The message of
// a pointer that cannot be set names the nearest one that exists.
BaseScene load_base(const std::string& path, const Grid& grid);

// The base document with `values` set at the grid's pointers.
Json variant_document(const BaseScene& base, const Grid& grid, const std::vector<Json>& values);

// The variant's scene text (2-space indented JSON, final newline).
std::string variant_text(const Json& document);

// FNV-1a (64 bits) of the variant's text and `salt` (what else shapes its
// outputs: formats, scale, pita's version), as 16 hex digits.
std::string content_hash(const std::string& text, const std::string& salt);

}  // namespace pita::sweep
