#include "engine/io/json_reader.hpp"

#include <charconv>
#include <cmath>
#include <unordered_set>
#include <vector>

namespace curvefold {
namespace {

using nlohmann::json;

// Appends value to out until out holds more than limit characters. Each level of nesting adds a
// bracket, so the recursion is at most limit deep whatever the value's depth.
void appendExcerpt(const json& value, std::string& out, std::size_t limit) {
  if (out.size() > limit) return;
  switch (value.type()) {
    case json::value_t::array: {
      out += '[';
      bool first = true;
      for (const json& element : value) {
        if (out.size() > limit) return;
        if (!first) out += ',';
        first = false;
        appendExcerpt(element, out, limit);
      }
      out += ']';
      return;
    }
    case json::value_t::object: {
      out += '{';
      bool first = true;
      for (const auto& [key, element] : value.items()) {
        if (out.size() > limit) return;
        if (!first) out += ',';
        first = false;
        out += quotedExcerpt(key, limit);
        out += ':';
        appendExcerpt(element, out, limit);
      }
      out += '}';
      return;
    }
    case json::value_t::string:
      out += quotedExcerpt(value.get_ref<const std::string&>(), limit);
      return;
    default:
      out += value.dump();
  }
}

std::string cut(std::string text, std::size_t maxLength) {
  if (text.size() <= maxLength) return text;
  text.resize(maxLength > 3 ? maxLength - 3 : 0);
  return text + "...";
}

}  // namespace

std::string shortestDouble(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

std::string jsonExcerpt(const json& value, std::size_t maxLength) {
  std::string out;
  appendExcerpt(value, out, maxLength);
  return cut(std::move(out), maxLength);
}

std::string jsonParseProblem(const json::exception& error) {
  std::string message = error.what();
  if (const auto start = message.find("] "); start != std::string::npos)
    message.erase(0, start + 2);
  return message;
}

namespace {

// The containers open around the parser's place, outermost first: each object's keys so far, each
// array's element count (for the path a message names). nlohmann's callback says the depth of
// every event but reports no end of a skipped container, so the stack is cut to the depth each
// event gives rather than popped at ends.
class KeyTracker {
 public:
  void event(int depth, json::parse_event_t event, const json& parsed) {
    const auto level = static_cast<std::size_t>(depth);
    if (event == json::parse_event_t::object_end || event == json::parse_event_t::array_end) return;
    if (open_.size() > level) open_.resize(level);
    // A value, an object or an array opening inside an array is its next element.
    if (event != json::parse_event_t::key && !open_.empty() && !open_.back().object)
      ++open_.back().elements;
    if (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start) {
      Container opened;
      opened.object = event == json::parse_event_t::object_start;
      open_.push_back(std::move(opened));
    } else if (event == json::parse_event_t::key && !open_.empty()) {
      Container& object = open_.back();
      const std::string& key = parsed.get_ref<const std::string&>();
      if (!object.keys.insert(key).second)
        throw JsonDuplicateKey("duplicate key " + quotedExcerpt(key) + " in " + where());
      object.key = key;
    }
  }

 private:
  struct Container {
    bool object = true;
    std::unordered_set<std::string> keys;
    std::string key;           // an object's member being read
    std::size_t elements = 0;  // an array's elements so far
  };

  // The object the last container is: "the top-level object", "surface.parameters", "folds[2]".
  std::string where() const {
    std::string path;
    for (std::size_t i = 0; i + 1 < open_.size(); ++i)
      path = open_[i].object ? JsonReader::join(path, open_[i].key)
                             : JsonReader::item(path, open_[i].elements - 1);
    return path.empty() ? "the top-level object" : path;
  }

  std::vector<Container> open_;
};

}  // namespace

json parseUniqueJson(std::string_view text, const JsonMemberFilter& keep) {
  KeyTracker keys;
  return json::parse(text, [&](int depth, json::parse_event_t event, json& parsed) {
    keys.event(depth, event, parsed);
    return event != json::parse_event_t::key || !keep ||
           keep(depth, parsed.get_ref<const std::string&>());
  });
}

json parseJsonText(std::string_view text, std::string_view name, const JsonMemberFilter& keep) {
  try {
    return parseUniqueJson(text, keep);
  } catch (const JsonDuplicateKey& e) {
    throw JsonReadError(std::string(name) + ": " + e.what());
  } catch (const json::parse_error& e) {
    // "parse error at line L, column C: problem": keep the place and the problem.
    std::string message = jsonParseProblem(e);
    std::string place;
    if (const auto at = message.find("parse error at "); at != std::string::npos) {
      message.erase(0, at + 15);
      if (const auto colon = message.find(": "); colon != std::string::npos) {
        place = " (" + message.substr(0, colon) + ")";
        message.erase(0, colon + 2);
      }
    }
    throw JsonReadError(std::string(name) + ": not valid JSON at byte " + std::to_string(e.byte) +
                        place + ": " + message);
  } catch (const json::exception& e) {
    // A number too large for a double, for instance.
    throw JsonReadError(std::string(name) + ": not valid JSON: " + jsonParseProblem(e));
  }
}

void JsonReader::fail(const std::string& where, const std::string& problem) const {
  throw JsonReadError(prefix_ + ": " + (where.empty() ? "" : where + ": ") + problem);
}

std::string JsonReader::join(const std::string& where, std::string_view key) {
  // Keys come from the file: quote only an excerpt of an absurd one.
  const std::string name = key.size() <= kJsonExcerptLength ? std::string(key) : quotedExcerpt(key);
  return where.empty() ? name : where + "." + name;
}

std::string JsonReader::item(const std::string& where, std::size_t index) {
  return where + "[" + std::to_string(index) + "]";
}

const json& JsonReader::object(const json& value, const std::string& where) const {
  if (!value.is_object()) fail(where, "must be an object, got " + std::string(value.type_name()));
  return value;
}

const json& JsonReader::array(const json& value, const std::string& where) const {
  if (!value.is_array()) fail(where, "must be an array, got " + std::string(value.type_name()));
  return value;
}

const json& JsonReader::member(const json& value, const char* key, const std::string& where) const {
  if (const json* found = optionalMember(value, key, where)) return *found;
  fail(where, std::string("missing \"") + key + "\"");
}

const json* JsonReader::optionalMember(const json& value, const char* key,
                                       const std::string& where) const {
  object(value, where);
  const auto it = value.find(key);
  return it == value.end() ? nullptr : &*it;
}

double JsonReader::number(const json& value, const std::string& where) const {
  // JSON has no NaN or infinity: nlohmann writes them as null, and huge literals do not parse.
  if (!value.is_number())
    fail(where, "must be a finite number, got " + std::string(value.type_name()));
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(where, "must be a finite number");
  return x;
}

double JsonReader::unitInterval(const json& value, const std::string& where) const {
  const double x = number(value, where);
  if (x < 0.0 || x > 1.0) fail(where, "must lie in [0, 1], got " + shortestDouble(x));
  return x;
}

bool JsonReader::boolean(const json& value, const std::string& where) const {
  if (!value.is_boolean())
    fail(where, "must be true or false, got " + std::string(value.type_name()));
  return value.get<bool>();
}

const std::string& JsonReader::string(const json& value, const std::string& where) const {
  if (!value.is_string()) fail(where, "must be a string, got " + std::string(value.type_name()));
  return value.get_ref<const std::string&>();
}

std::uint64_t JsonReader::unsignedInteger(const json& value, const std::string& where) const {
  if (!value.is_number_unsigned())
    fail(where, "must be a non-negative integer, got " + jsonExcerpt(value));
  return value.get<std::uint64_t>();
}

void JsonReader::numbers(const json& value, std::size_t n, double* out,
                         const std::string& where) const {
  if (!value.is_array() || value.size() != n)
    fail(where, "must be an array of " + std::to_string(n) + " numbers, got " +
                    (value.is_array() ? std::to_string(value.size()) + " values"
                                      : std::string(value.type_name())));
  for (std::size_t i = 0; i < n; ++i) out[i] = number(value[i], item(where, i));
}

glm::dvec2 JsonReader::vector2(const json& value, const std::string& where) const {
  double c[2];
  numbers(value, 2, c, where);
  return {c[0], c[1]};
}

glm::dvec3 JsonReader::vector3(const json& value, const std::string& where) const {
  double c[3];
  numbers(value, 3, c, where);
  return {c[0], c[1], c[2]};
}

std::int64_t JsonReader::formatAndVersion(const json& document, std::string_view format,
                                          std::int64_t oldest, std::int64_t newest,
                                          std::string_view what) const {
  if (!document.is_object())
    fail("", "not a " + std::string(what) + " (a JSON " + std::string(document.type_name()) +
                 ", not an object)");
  const auto name = document.find("format");
  if (name == document.end()) fail("", "not a " + std::string(what) + " (no \"format\")");
  if (!name->is_string() || name->get_ref<const std::string&>() != format)
    fail("", "not a " + std::string(what) + " (format " + jsonExcerpt(*name) + ", expected \"" +
                 std::string(format) + "\")");
  const json& found = member(document, "version", "");
  const std::string reads =
      oldest == newest ? "version " + std::to_string(newest)
                       : "versions " + std::to_string(oldest) + " to " + std::to_string(newest);
  if (found.is_number_integer()) {
    const std::int64_t version = found.get<std::int64_t>();
    if (version > newest)
      fail("", "unsupported version " + std::to_string(version) +
                   ", newer than this build reads (" + reads + "): open it with a newer curvefold");
    if (version >= oldest) return version;
  }
  fail("", "unsupported version " + jsonExcerpt(found) + " (this build reads " + reads + ")");
}

}  // namespace curvefold
