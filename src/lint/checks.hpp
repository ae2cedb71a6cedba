// The checks of the lint, one function per row of scene::kLintChecks, in
// that order (lint/lint.hpp).
#pragma once

#include <span>
#include <vector>

#include "lint/geometry.hpp"
#include "lint/lint.hpp"
#include "scene/lint_settings.hpp"

namespace pita::lint {

using Check = void (*)(const FigureGeometry& figure, const scene::LintSettings& settings,
                       std::vector<Finding>& findings);

// check_functions()[k] computes scene::kLintChecks[k].
std::span<const Check> check_functions();

}  // namespace pita::lint
