// "claims": the caption's statements as predicates over panel measures
// (scene/claim.hpp; docs/reference/check.md "Claims").
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "scene/scene_readers.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 10> kClaimFields = {"says",  "panel", "layer", "measure", "absolute",
                                                           "below", "above", "near",  "within",  "is"};
constexpr std::array<std::string_view, 4> kOperandFields = {"panel", "measure", "times", "plus"};
constexpr std::array<std::string_view, 4> kTests = {"below", "above", "near", "is"};

// A panel's index: required when the scene has several panels.
std::size_t read_panel_index(const JsonReader& reader, const Json& object, const std::string& pointer,
                             const Scene& scene, std::size_t fallback, bool required) {
  const Json* panel = JsonReader::member(object, "panel");
  if (panel == nullptr) {
    if (required && scene.panels.size() > 1) {
      reader.fail(pointer, fmt::format("a claim names its panel, \"panel\": an index from 0 to {} (the scene has {} "
                                       "panels)",
                                       scene.panels.size() - 1, scene.panels.size()));
    }
    return fallback;
  }
  return static_cast<std::size_t>(
      reader.integer(*panel, pointer + "/panel", 0, static_cast<int>(scene.panels.size()) - 1));
}

template <class LayerType>
MeasureName read_measure(const JsonReader& reader, const Json& value, const std::string& pointer, const Scene& scene) {
  auto parsed = parse_measure<LayerType>(reader.text(value, pointer, 200));
  if (const std::string* reason = std::get_if<std::string>(&parsed)) reader.fail(pointer, *reason);
  MeasureName measure = std::move(std::get<MeasureName>(parsed));
  if (measure.panel && *measure.panel >= scene.panels.size()) {
    reader.fail(pointer, fmt::format("\"{}\" names panel {}, and the scene has {} (indices 0 to {})", measure.text,
                                     *measure.panel, scene.panels.size(), scene.panels.size() - 1));
  }
  return measure;
}

template <class LayerType>
ClaimBound read_bound(const JsonReader& reader, const Json& value, const std::string& pointer, const Scene& scene,
                      const Claim& claim) {
  if (value.is_number()) return reader.number(value, pointer);
  if (!value.is_object()) {
    reader.fail(pointer, fmt::format("must be a number or a panel's measure {{\"panel\", \"measure\", \"times\", "
                                     "\"plus\"}} (got {})",
                                     value_text(value)));
  }
  reader.check_fields(value, pointer, kOperandFields);
  ClaimOperand operand;
  operand.panel = read_panel_index(reader, value, pointer, scene, claim.panel, false);
  operand.measure = claim.measure;
  if (const Json* measure = JsonReader::member(value, "measure")) {
    operand.measure = read_measure<LayerType>(reader, *measure, pointer + "/measure", scene);
  }
  if (const Json* times = JsonReader::member(value, "times")) operand.times = reader.number(*times, pointer + "/times");
  if (const Json* plus = JsonReader::member(value, "plus")) operand.plus = reader.number(*plus, pointer + "/plus");
  return operand;
}

template <class LayerType>
Claim read_claim(const JsonReader& reader, const Json& value, const std::string& pointer, const Scene& scene) {
  reader.object(value, pointer, "a claim");
  reader.check_fields(value, pointer, kClaimFields);
  Claim claim;
  claim.pointer = pointer;
  const Json* says = JsonReader::member(value, "says");
  if (says == nullptr) reader.fail(pointer, "a claim says what it claims, in words: \"says\"");
  claim.says = reader.text(*says, pointer + "/says", kMaxClaimText);
  claim.panel = read_panel_index(reader, value, pointer, scene, 0, true);
  const Json* measure = JsonReader::member(value, "measure");
  if (measure == nullptr) reader.fail(pointer, "a claim names the measure it compares: \"measure\"");
  claim.measure = read_measure<LayerType>(reader, *measure, pointer + "/measure", scene);
  if (const Json* layer = JsonReader::member(value, "layer")) {
    if (claim.measure.kind != MeasureKind::frame_distance) {
      reader.fail(pointer + "/layer",
                  fmt::format("\"layer\" names the layer whose motion a \"frame-distance\" claim compares, and "
                              "this claim measures \"{}\"",
                              claim.measure.text));
    }
    claim.layer = static_cast<std::size_t>(reader.integer(*layer, pointer + "/layer", 0, kMaxLayers - 1));
  }
  if (const Json* absolute = JsonReader::member(value, "absolute")) {
    claim.absolute = reader.boolean(*absolute, pointer + "/absolute");
  }

  const Json* test = nullptr;
  std::string_view test_name;
  for (const std::string_view name : kTests) {
    const Json* given = JsonReader::member(value, std::string(name));
    if (given == nullptr) continue;
    if (test != nullptr) {
      reader.fail(pointer + "/" + std::string(name),
                  fmt::format("a claim makes one test, and this one has \"{}\" too", test_name));
    }
    test = given;
    test_name = name;
  }
  if (test == nullptr) {
    reader.fail(pointer, fmt::format("a claim tests its measure with one of {}", quoted_choices(kTests)));
  }
  const std::string at = pointer + "/" + std::string(test_name);
  const Json* within = JsonReader::member(value, "within");
  if (within != nullptr && test_name != "near") {
    reader.fail(pointer + "/within", "\"within\" is the tolerance of \"near\", and this claim has none");
  }
  if (test_name == "below") {
    claim.test = Below{read_bound<LayerType>(reader, *test, at, scene, claim)};
  } else if (test_name == "above") {
    claim.test = Above{read_bound<LayerType>(reader, *test, at, scene, claim)};
  } else if (test_name == "near") {
    Near near{read_bound<LayerType>(reader, *test, at, scene, claim), 0.0};
    if (within != nullptr) near.within = reader.number(*within, pointer + "/within", Interval{0.0, 1e6});
    claim.test = near;
  } else {
    if (claim.measure.kind != MeasureKind::pop) {
      reader.fail(at, fmt::format("\"is\" tests a yes-or-no measure (\"pop\"), and \"{}\" is a number: compare it "
                                  "with \"below\", \"above\" or \"near\"",
                                  claim.measure.text));
    }
    claim.test = Is{reader.boolean(*test, at)};
  }
  return claim;
}

}  // namespace

template <class LayerType>
std::vector<Claim> read_claims(const JsonReader& reader, const Json& value, const Scene& scene) {
  if (!value.is_array() || value.size() > static_cast<std::size_t>(kMaxClaims)) {
    reader.fail("/claims", fmt::format("must be a list of at most {} claims (got {})", kMaxClaims, value_text(value)));
  }
  std::vector<Claim> claims;
  for (std::size_t i = 0; i < value.size(); ++i) {
    claims.push_back(read_claim<LayerType>(reader, value[i], element_pointer("/claims", i), scene));
  }
  return claims;
}

template std::vector<Claim> read_claims<Layer>(const JsonReader&, const Json&, const Scene&);
template std::vector<Claim> read_claims<PoseLayer>(const JsonReader&, const Json&, const Scene&);

}  // namespace pita::scene::detail
