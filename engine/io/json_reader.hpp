// Typed reads from parsed JSON with one-line messages that say where a value is wrong: the one set
// of helpers behind the design reader, the recording reader and the gesture-script reader.
//
// Messages never print a whole value: a value is quoted by jsonExcerpt, at most about 60
// characters, whatever its size or depth (a value nested a million deep must not turn an error
// message into a stack overflow).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "engine/geometry/sheet.hpp"
#include "engine/text/excerpt.hpp"

namespace curvefold {

// Vertex and triangle indices read and written as the integers they are (nlohmann finds these by
// argument-dependent lookup).
template <typename Json, typename Tag>
void to_json(Json& json, ElementIndex<Tag> index) {
  json = index.value;
}
template <typename Json, typename Tag>
void from_json(const Json& json, ElementIndex<Tag>& index) {
  index.value = json.template get<std::uint32_t>();
}

// "<prefix>: <where>: <problem>", one line. Each format's reader turns it into its own error type.
class JsonReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The longest excerpt of a value or key a message quotes.
inline constexpr std::size_t kJsonExcerptLength = kExcerptLength;

// A single-line excerpt of value, ending in "..." when cut; its cost is bounded by maxLength,
// not by the value's size or depth.
std::string jsonExcerpt(const nlohmann::json& value, std::size_t maxLength = kJsonExcerptLength);
// A string (an object key, a name read from a file) is quoted and cut by quotedExcerpt.

// Which object members to keep while parsing: keep(depth, key), depth 1 for the document's own
// members. A member not kept is skipped as it is parsed, never built.
using JsonMemberFilter = std::function<bool(int depth, std::string_view key)>;

// The shortest text that reads back as the same double, for messages and lines.
std::string shortestDouble(double value);

// A key an object holds twice. JSON leaves its meaning open and nlohmann keeps the last (a second
// "folds": [] would drop every fold before it), so every reader refuses it: "duplicate key
// "folds" in the top-level object", "duplicate key "x" in surface.parameters".
class JsonDuplicateKey : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// nlohmann's parse with every object's keys checked unique (JsonDuplicateKey) and the members
// `keep` refuses skipped; nlohmann's own exceptions pass as they are. The one parse behind
// parseJsonText and the recording's lines.
nlohmann::json parseUniqueJson(std::string_view text, const JsonMemberFilter& keep = {});

// Parses text; throws JsonReadError "<name>: not valid JSON at byte B (line L, column C): problem"
// or "<name>: duplicate key ...".
nlohmann::json parseJsonText(std::string_view text, std::string_view name,
                             const JsonMemberFilter& keep = {});
// nlohmann's message without its "[json.exception...]" tag, for a parse inside a larger report.
std::string jsonParseProblem(const nlohmann::json::exception& error);

class JsonReader {
 public:
  // prefix starts every message: a file name, or "file: line 7".
  explicit JsonReader(std::string prefix) : prefix_(std::move(prefix)) {}

  const std::string& prefix() const { return prefix_; }

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const;

  // "a.b" (or "b" at the top), "a[3]".
  static std::string join(const std::string& where, std::string_view key);
  static std::string item(const std::string& where, std::size_t index);

  const nlohmann::json& object(const nlohmann::json& value, const std::string& where) const;
  const nlohmann::json& array(const nlohmann::json& value, const std::string& where) const;
  const nlohmann::json& member(const nlohmann::json& object, const char* key,
                               const std::string& where) const;
  // nullptr when the key is absent; fails when object is not an object.
  const nlohmann::json* optionalMember(const nlohmann::json& object, const char* key,
                                       const std::string& where) const;

  double number(const nlohmann::json& value, const std::string& where) const;  // finite
  double unitInterval(const nlohmann::json& value, const std::string& where) const;
  bool boolean(const nlohmann::json& value, const std::string& where) const;
  const std::string& string(const nlohmann::json& value, const std::string& where) const;
  std::uint64_t unsignedInteger(const nlohmann::json& value, const std::string& where) const;

  // An array of exactly n finite numbers, written into out.
  void numbers(const nlohmann::json& value, std::size_t n, double* out,
               const std::string& where) const;
  glm::dvec2 vector2(const nlohmann::json& value, const std::string& where) const;
  glm::dvec3 vector3(const nlohmann::json& value, const std::string& where) const;

  // Checks a document's "format" and "version" members, quoting only an excerpt of what is there:
  // "not a <what> (format [[[[..., expected "curvefold-design")".
  void formatAndVersion(const nlohmann::json& document, std::string_view format,
                        std::int64_t version, std::string_view what) const {
    formatAndVersion(document, format, version, version, what);
  }
  // Any version from oldest to newest; returns the one read. A newer one is refused saying that a
  // newer curvefold wrote it: "unsupported version 3, newer than this build reads (versions 1 to
  // 2): open it with a newer curvefold".
  std::int64_t formatAndVersion(const nlohmann::json& document, std::string_view format,
                                std::int64_t oldest, std::int64_t newest,
                                std::string_view what) const;

 private:
  std::string prefix_;
};

}  // namespace curvefold
