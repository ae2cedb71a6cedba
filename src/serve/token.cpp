#include "serve/token.hpp"

#include <cstdlib>
#include <random>
#include <stdexcept>

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/fnv1a.hpp"
#include "io/input_file.hpp"
#include "io/output_file.hpp"

namespace pita::serve {

namespace {

namespace fs = std::filesystem;

// STATE/pita/serve-tokens, made 0700 when missing; refused when another user
// owns it or others may enter it.
fs::path token_folder() {
  const char* state = std::getenv("XDG_STATE_HOME");
  const char* home = std::getenv("HOME");
  fs::path base;
  if (state != nullptr && *state == '/') {
    base = state;
  } else if (home != nullptr && *home == '/') {
    base = fs::path(home) / ".local" / "state";
  } else {
    throw std::runtime_error("neither XDG_STATE_HOME nor HOME names a folder to keep the token in");
  }
  const fs::path folder = base / "pita" / "serve-tokens";
  fs::create_directories(folder);
  fs::permissions(folder.parent_path(), fs::perms::owner_all, fs::perm_options::replace);
  fs::permissions(folder, fs::perms::owner_all, fs::perm_options::replace);
  struct stat st {};
  if (::lstat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::getuid() || (st.st_mode & 077) != 0) {
    throw std::runtime_error(fmt::format("{}: not a private folder of this user", folder.string()));
  }
  return folder;
}

// The token kept in `file` when it is a private regular file of this user holding a valid token.
std::optional<std::string> read_kept(const fs::path& file) {
  struct stat st {};
  if (::lstat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::getuid() || (st.st_mode & 077) != 0) {
    return std::nullopt;
  }
  try {
    std::string token = io::read_regular_file(file, 256);
    while (!token.empty() && (token.back() == '\n' || token.back() == '\r')) token.pop_back();
    if (token_problem(token)) return std::nullopt;
    return token;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::string random_token() {
  std::random_device source;
  std::string token;
  for (int i = 0; i < 4; ++i) token += fmt::format("{:08x}", source());
  return token;
}

std::optional<std::string> token_problem(const std::string& token) {
  if (token.size() < 16 || token.size() > 128) {
    return fmt::format("a token has 16 to 128 characters (got {})", token.size());
  }
  for (const char c : token) {
    const bool fits =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
    if (!fits) return "a token holds letters, digits, '-' and '_' only (it stands in the page's address as it is)";
  }
  return std::nullopt;
}

std::string kept_token(const fs::path& folder, bool fresh) {
  Fnv1a hash;
  hash.add(fs::weakly_canonical(folder).string());
  const fs::path file = token_folder() / fmt::format("{:016x}", hash.value());
  if (!fresh) {
    if (const auto kept = read_kept(file)) return *kept;
  }
  const std::string token = random_token();
  io::write_file_atomically(file, token + "\n");
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
  return token;
}

}  // namespace pita::serve
