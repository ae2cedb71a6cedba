// The token of `pita serve` (docs/reference/serve.md "Security"): drawn at
// random for each start, given with --token, or kept for the folder with
// --keep-token, so that a restart reconnects the tabs already open.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace pita::serve {

// A random token: 32 hexadecimal digits (128 bits) from the system's random source.
std::string random_token();

// What is wrong with a token given with --token (16 to 128 letters, digits,
// '-' or '_', so that it stands in a URL as it is), or nullopt.
std::optional<std::string> token_problem(const std::string& token);

// The token kept for `folder` (canonical) in STATE/pita/serve-tokens/<hash>,
// STATE being $XDG_STATE_HOME or ~/.local/state: read when it is there (a
// regular file of its owner that no one else may read, holding a valid
// token), else drawn and written there, the file 0600 in folders 0700.
// `fresh`: drawn anew even when one is kept (--new-token). Throws
// std::runtime_error naming the file when it cannot be kept.
std::string kept_token(const std::filesystem::path& folder, bool fresh);

}  // namespace pita::serve
