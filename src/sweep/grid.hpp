// The variants of a sweep (docs/reference/sweep.md "pita sweep"): each --vary POINTER=SPEC is
// an axis of values set at a JSON Pointer of the scene; several axes make
// their Cartesian product (the last axis varies fastest), or with --zip are
// paired value by value. A variant is named by its index; its values are
// computed from the index, never stored, so a sweep of 10^7 variants costs no
// memory.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace pita::sweep {

using Json = nlohmann::ordered_json;

// The inputs of a sweep that its errors are about. A front end names each in
// its own words (the CLI: --vary, --zip, -o, --jobs, --merge, --shard, --wait,
// --force; cli/sweep_options.cpp): no message of src/sweep names an option.
enum class Input { none, vary, zip, output, jobs, merge, shard, wait, force };

// What an error of a sweep is about: the input and the argument given for it
// ("/keyframes/1/t=0:1:3", "out"), and the input that would let it pass (wait,
// force) or make what is missing (shard), which a front end may suggest.
struct About {
  About() = default;
  explicit About(Input about, std::string given = {}, Input would_pass = Input::none)
      : input(about), argument(std::move(given)), remedy(would_pass) {}
  Input input = Input::none;
  std::string argument;
  Input remedy = Input::none;
};

// An error of `Base` about an input: what() is "ARGUMENT: REASON" (REASON
// when no argument is given); a front end names the input before it.
template <class Base>
class AboutInput : public Base {
 public:
  explicit AboutInput(const std::string& reason) : Base(reason), reason_(reason) {}
  AboutInput(About about, const std::string& reason)
      : Base(about.argument.empty() ? reason : about.argument + ": " + reason),
        about_(std::move(about)),
        reason_(reason) {}
  const About& about() const { return about_; }
  const std::string& reason() const { return reason_; }

 private:
  About about_;
  std::string reason_;
};

// Bad usage of pita sweep (exit 2).
using SweepUsageError = AboutInput<std::runtime_error>;

// The largest sweep: product (or zipped length) of the axes.
inline constexpr std::int64_t kMaxVariants = 10'000'000;

// One axis: its values are computed on demand (a range of 10^7 values costs
// nothing), numbers with integral values as JSON integers.
struct Axis {
  enum class Kind { linear, geometric, list };
  std::string pointer;  // "/keyframes/1/t"
  std::string spec;     // as typed: "0.2:0.8:7"
  Kind kind = Kind::list;
  double a = 0, b = 0;      // linear, geometric: the ends
  std::int64_t n = 0;       // linear, geometric: the count
  std::vector<Json> items;  // list

  std::size_t size() const { return kind == Kind::list ? items.size() : static_cast<std::size_t>(n); }
  Json value(std::size_t i) const;
};

// POINTER=SPEC, SPEC one of
//   a:b:n      n values from a to b inclusive (n >= 1; n = 1 gives a)
//   log:a:b:n  n values from a to b in geometric progression (a, b of one sign, not 0)
//   v1,v2,...  a list: each a JSON number, true, false or null, else a string
// Throws SweepUsageError naming the argument.
Axis parse_axis(std::string_view argument);

class Grid {
 public:
  Grid() = default;
  // Throws SweepUsageError: no axis, a pointer given twice, --zip with
  // unequal lengths, more than kMaxVariants variants.
  Grid(std::vector<Axis> axes, bool zip);

  const std::vector<Axis>& axes() const { return axes_; }
  bool zip() const { return zip_; }
  std::int64_t size() const { return size_; }
  // The value index on each axis of variant `index` (0 <= index < size()).
  std::vector<std::size_t> positions(std::int64_t index) const;
  // The values of variant `index`, one per axis.
  std::vector<Json> values(std::int64_t index) const;

 private:
  std::vector<Axis> axes_;
  bool zip_ = false;
  std::int64_t size_ = 0;
};

// A value as the manifest and the labels print it: numbers in shortest
// round-trip form, strings as they are.
std::string value_text(const Json& value);

}  // namespace pita::sweep
