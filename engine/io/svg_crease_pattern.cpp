#include "engine/io/svg_crease_pattern.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <unordered_map>

#include <libxml/parser.h>
#include <libxml/tree.h>
#include <glm/geometric.hpp>

#include "engine/io/crease_pattern_graph.hpp"
#include "engine/io/input_limits.hpp"
#include "engine/io/json_reader.hpp"
#include "engine/text/excerpt.hpp"

namespace curvefold {
namespace {

// A 2D affine map: x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  glm::dvec2 operator()(glm::dvec2 p) const {
    return {a * p.x + c * p.y + e, b * p.x + d * p.y + f};
  }
  Affine operator*(const Affine& r) const {
    return {a * r.a + c * r.b, b * r.a + d * r.b,     a * r.c + c * r.d,
            b * r.c + d * r.d, a * r.e + c * r.f + e, b * r.e + d * r.f + f};
  }
};

// Numbers in attribute text: SVG's grammar (wsp and commas between, "1-2" and ".5.5" two each).
class NumberScanner {
 public:
  explicit NumberScanner(std::string_view text) : text_(text) {}
  void skipSeparators() {
    while (pos_ < text_.size() &&
           (std::isspace(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == ','))
      ++pos_;
  }
  bool atEnd() {
    skipSeparators();
    return pos_ >= text_.size();
  }
  char peek() {
    skipSeparators();
    return pos_ < text_.size() ? text_[pos_] : '\0';
  }
  void advance() { ++pos_; }
  std::size_t position() const { return pos_; }
  bool startsNumber() {
    const char ch = peek();
    return std::isdigit(static_cast<unsigned char>(ch)) || ch == '-' || ch == '+' || ch == '.';
  }
  std::optional<double> number() {
    skipSeparators();
    std::size_t end = pos_;
    if (end < text_.size() && (text_[end] == '-' || text_[end] == '+')) ++end;
    bool digits = false, dot = false;
    while (end < text_.size()) {
      const char ch = text_[end];
      if (std::isdigit(static_cast<unsigned char>(ch))) {
        digits = true;
      } else if (ch == '.' && !dot) {
        dot = true;
      } else {
        break;
      }
      ++end;
    }
    if (!digits) return std::nullopt;
    if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
      std::size_t exponent = end + 1;
      if (exponent < text_.size() && (text_[exponent] == '-' || text_[exponent] == '+')) ++exponent;
      if (exponent < text_.size() && std::isdigit(static_cast<unsigned char>(text_[exponent]))) {
        end = exponent;
        while (end < text_.size() && std::isdigit(static_cast<unsigned char>(text_[end]))) ++end;
      }
    }
    std::size_t start = pos_;
    if (text_[start] == '+') ++start;
    double value = 0.0;
    const auto result = std::from_chars(text_.data() + start, text_.data() + end, value);
    if (result.ec != std::errc() || !std::isfinite(value)) return std::nullopt;
    pos_ = end;
    return value;
  }
  // An arc flag: a single 0 or 1, which may run into the next number.
  std::optional<double> flag() {
    const char ch = peek();
    if (ch != '0' && ch != '1') return std::nullopt;
    ++pos_;
    return ch == '1' ? 1.0 : 0.0;
  }
  // Skips a unit or percent sign after a number; returns it.
  std::string_view skipUnit() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalpha(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '%'))
      ++pos_;
    return text_.substr(start, pos_ - start);
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& ch : out) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return out;
}

std::string trim(std::string_view text) {
  std::size_t start = 0, end = text.size();
  while (start < end && std::isspace(static_cast<unsigned char>(text[start]))) ++start;
  while (end > start && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  return std::string(text.substr(start, end - start));
}

using Declarations = std::map<std::string, std::string>;

// "a: b; c: d" into {a: b, c: d}; names lower case.
void parseDeclarations(std::string_view text, Declarations& out) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(';', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view item = text.substr(start, end - start);
    if (const auto colon = item.find(':'); colon != std::string_view::npos) {
      std::string value = trim(item.substr(colon + 1));
      if (const auto important = lower(value).find("!important"); important != std::string::npos)
        value = trim(std::string_view(value).substr(0, important));
      out[lower(trim(item.substr(0, colon)))] = value;
    }
    start = end + 1;
  }
}

struct CssRules {
  std::unordered_map<std::string, Declarations> byTag, byClass, byTagClass;
};

// The simple rules of a <style> sheet: ".a, line, path.b { ... }"; others are skipped.
void parseStyleSheet(std::string text, CssRules& rules) {
  for (std::size_t comment; (comment = text.find("/*")) != std::string::npos;) {
    const std::size_t close = text.find("*/", comment + 2);
    text.erase(comment, close == std::string::npos ? std::string::npos : close + 2 - comment);
  }
  std::size_t start = 0;
  while (true) {
    const std::size_t open = text.find('{', start);
    if (open == std::string::npos) return;
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) return;
    Declarations declarations;
    parseDeclarations(std::string_view(text).substr(open + 1, close - open - 1), declarations);
    std::string_view selectors = std::string_view(text).substr(start, open - start);
    std::size_t from = 0;
    while (from <= selectors.size()) {
      std::size_t comma = selectors.find(',', from);
      if (comma == std::string_view::npos) comma = selectors.size();
      const std::string selector = trim(selectors.substr(from, comma - from));
      from = comma + 1;
      if (selector.empty() || selector.find_first_of(" >+~[:#*") != std::string::npos) continue;
      const auto dot = selector.find('.');
      auto& table = dot == 0                   ? rules.byClass
                    : dot == std::string::npos ? rules.byTag
                                               : rules.byTagClass;
      const std::string key = dot == 0 ? selector.substr(1) : lower(selector);
      for (const auto& [name, value] : declarations) table[key][name] = value;
    }
    start = close + 1;
  }
}

// `alpha`: the colour's own opacity (#rgba, #rrggbbaa, rgba(), rgb(r g b / a)), 1 without one.
std::optional<std::array<int, 3>> parseColour(const std::string& text, bool& namedGreen,
                                              double& alpha) {
  const std::string value = lower(trim(text));
  namedGreen = value == "green";
  alpha = 1.0;
  static const std::unordered_map<std::string, std::array<int, 3>> named = {
      {"black", {0, 0, 0}},       {"red", {255, 0, 0}},       {"blue", {0, 0, 255}},
      {"lime", {0, 255, 0}},      {"green", {0, 128, 0}},     {"yellow", {255, 255, 0}},
      {"magenta", {255, 0, 255}}, {"fuchsia", {255, 0, 255}}, {"white", {255, 255, 255}}};
  if (const auto found = named.find(value); found != named.end()) return found->second;
  if (!value.empty() && value[0] == '#') {
    const std::string hex = value.substr(1);
    if (hex.find_first_not_of("0123456789abcdef") != std::string::npos) return std::nullopt;
    const auto digit = [&](std::size_t k) { return std::stoi(hex.substr(k, 1), nullptr, 16); };
    if (hex.size() == 4) alpha = digit(3) * 17 / 255.0;
    if (hex.size() == 8) alpha = std::stoi(hex.substr(6, 2), nullptr, 16) / 255.0;
    if (hex.size() == 3 || hex.size() == 4)
      return std::array<int, 3>{digit(0) * 17, digit(1) * 17, digit(2) * 17};
    if (hex.size() == 6 || hex.size() == 8)
      return std::array<int, 3>{std::stoi(hex.substr(0, 2), nullptr, 16),
                                std::stoi(hex.substr(2, 2), nullptr, 16),
                                std::stoi(hex.substr(4, 2), nullptr, 16)};
    return std::nullopt;
  }
  if (value.rfind("rgb(", 0) == 0 || value.rfind("rgba(", 0) == 0) {
    const std::size_t open = value.find('(');
    const std::size_t close = value.find(')', open);
    if (close == std::string::npos) return std::nullopt;
    std::string inside = value.substr(open + 1, close - open - 1);
    std::replace(inside.begin(), inside.end(), '/', ' ');
    NumberScanner scanner(inside);
    std::array<int, 3> rgb{};
    for (int k = 0; k < 3; ++k) {
      const auto number = scanner.number();
      if (!number) return std::nullopt;
      double channel = *number;
      if (scanner.peek() == '%') {
        scanner.advance();
        channel *= 2.55;
      }
      rgb[k] = static_cast<int>(std::lround(std::clamp(channel, 0.0, 255.0)));
    }
    // The fourth number, after a comma or CSS4's slash: a fraction or a percentage.
    if (const auto a = scanner.number()) {
      alpha = *a;
      if (scanner.peek() == '%') alpha /= 100.0;
      alpha = std::clamp(alpha, 0.0, 1.0);
    }
    return rgb;
  }
  return std::nullopt;
}

// Origami Simulator's colours (js/pattern.js typeForStroke).
std::optional<CreaseAssignment> assignmentForColour(const std::array<int, 3>& rgb,
                                                    bool namedGreen) {
  if (namedGreen) return CreaseAssignment::Cut;
  const std::array<std::pair<std::array<int, 3>, CreaseAssignment>, 6> table = {{
      {{0, 0, 0}, CreaseAssignment::Boundary},
      {{255, 0, 0}, CreaseAssignment::Mountain},
      {{0, 0, 255}, CreaseAssignment::Valley},
      {{0, 255, 0}, CreaseAssignment::Cut},
      {{255, 255, 0}, CreaseAssignment::Flat},
      {{255, 0, 255}, CreaseAssignment::Unassigned},
  }};
  for (const auto& [colour, assignment] : table)
    if (colour == rgb) return assignment;
  return std::nullopt;
}

// What the elements above an element pass down.
struct Inherited {
  Affine transform;
  std::string stroke;  // empty: none given
  std::string strokeOpacity;
  std::string color;  // CSS's color, what stroke="currentColor" takes
};

class SvgReader {
 public:
  SvgReader(std::string_view name, CreaseDrawing& drawing) : name_(name), drawing_(drawing) {}

  [[noreturn]] void fail(const xmlNode* node, const std::string& problem) const {
    throw CreasePatternError(name_ + ": line " + std::to_string(xmlGetLineNo(node)) + ": " +
                             problem);
  }

  void collectStyles(const xmlNode* node) {
    for (const xmlNode* child = node; child; child = child->next) {
      if (child->type != XML_ELEMENT_NODE) continue;
      // Every element with an id, for <use> (the first of a repeated id, as a browser takes it).
      if (const auto id = attribute(child, "id")) ids_.try_emplace(*id, child);
      if (localName(child) == "style") {
        xmlChar* content = xmlNodeGetContent(child);
        if (content) {
          parseStyleSheet(reinterpret_cast<const char*>(content), rules_);
          xmlFree(content);
        }
      } else {
        collectStyles(child->children);
      }
    }
  }

  void walk(const xmlNode* node, const Inherited& parent) {
    for (const xmlNode* child = node; child; child = child->next)
      if (child->type == XML_ELEMENT_NODE) visit(child, parent);
  }

  // One element and what it holds. `referenced`: reached through a <use>, so a <symbol> draws.
  void visit(const xmlNode* child, const Inherited& parent, bool referenced = false) {
    // Every element drawn again through a <use> counts against the copy budget, so uses nested
    // over a large group cannot ask for more work than the file's own elements many times over.
    if (useDepth_ > 0 && ++useCopies_ > kMaxUseCopies)
      fail(child, "<use> copies past the limit of " + std::to_string(kMaxUseCopies) +
                      " elements drawn again");
    {
      const std::string tag = localName(child);
      static const char* const hidden[] = {
          "defs",           "symbol", "clippath",  "mask",         "marker", "pattern",
          "metadata",       "title",  "desc",      "style",        "script", "lineargradient",
          "radialgradient", "filter", "namedview", "foreignobject"};
      if (!(referenced && lower(tag) == "symbol") &&
          std::find_if(std::begin(hidden), std::end(hidden),
                       [&](const char* h) { return lower(tag) == h; }) != std::end(hidden))
        return;
      Declarations style = declarationsOf(child, tag);
      if (lower(valueOf(style, "display")) == "none") return;
      Inherited here = parent;
      // The attribute, or a style rule's or style="..."'s transform property over it (SVG 2
      // made it a presentation attribute; Rabbit Ear's test files scale the border so).
      if (const std::string transform = valueOf(style, "transform");
          !transform.empty() && lower(transform) != "none")
        here.transform = parent.transform * parseTransform(child, transform);
      if (const std::string stroke = valueOf(style, "stroke");
          !stroke.empty() && stroke != "inherit")
        here.stroke = stroke;
      if (const std::string opacity = valueOf(style, "stroke-opacity");
          !opacity.empty() && opacity != "inherit")
        here.strokeOpacity = opacity;
      if (const std::string color = valueOf(style, "color"); !color.empty() && color != "inherit")
        here.color = color;
      if (tag == "g" || tag == "svg" || tag == "a" || tag == "switch" || tag == "symbol") {
        walk(child->children, here);
        return;
      }
      if (tag == "line" || tag == "polyline" || tag == "polygon" || tag == "rect" ||
          tag == "path" || tag == "circle" || tag == "ellipse") {
        shape(child, tag, here, style);
        return;
      }
      if (tag == "use") {
        use(child, here);
        return;
      }
      ++ignoredElements_[tag];
    }
  }

  // <use href="#id" x y>: the element with that id drawn again, moved by x and y after the
  // use's transform, with the use's stroke (Inkscape's clones and tiled clones, Illustrator's
  // symbols). A reference to itself or an ancestor, or past the copy budget, fails in one line.
  void use(const xmlNode* node, const Inherited& here) {
    auto href = attribute(node, "href");  // xlink:href too: xmlGetProp ignores the namespace
    if (!href || href->empty() || (*href)[0] != '#') {
      ++ignoredElements_["use"];
      return;
    }
    const auto found = ids_.find(href->substr(1));
    if (found == ids_.end()) fail(node, "<use> of " + quotedExcerpt(*href, 40) + ": no such id");
    for (const xmlNode* up = node; up; up = up->parent)
      if (up == found->second) fail(node, "<use> of " + quotedExcerpt(*href, 40) + " draws itself");
    if (useDepth_ >= kMaxUseDepth || drawing_.lines.size() > kMaxCreasePatternEdges)
      fail(node, "<use> copies past the limits (" + std::to_string(kMaxUseDepth) + " nested, " +
                     std::to_string(kMaxCreasePatternEdges) + " lines)");
    Inherited moved = here;
    Affine shift;
    shift.e = length(node, "x");
    shift.f = length(node, "y");
    moved.transform = here.transform * shift;
    ++useDepth_;
    visit(found->second, moved, true);
    --useDepth_;
  }

  void finish() {
    if (!unknownColours_.empty()) {
      std::string line = "ignored shapes with strokes of no crease colour:";
      std::size_t k = 0;
      for (const auto& [colour, count] : unknownColours_) {
        if (k++ == 6) {
          line += " and " + std::to_string(unknownColours_.size() - 6) + " more colours";
          break;
        }
        line +=
            (k > 1 ? ", " : " ") + quotedExcerpt(colour, 30) + " (" + std::to_string(count) + ")";
      }
      drawing_.notes.push_back(line);
    }
    if (noStroke_ > 0)
      drawing_.notes.push_back(std::to_string(noStroke_) + " shapes without a stroke ignored");
    if (!ignoredElements_.empty()) {
      std::string line = "elements not read:";
      std::size_t k = 0;
      for (const auto& [tag, count] : ignoredElements_)
        line += (k++ ? ", <" : " <") + tag + "> (" + std::to_string(count) + ")";
      drawing_.notes.push_back(line);
    }
    if (flattenedCurves_ > 0)
      drawing_.notes.push_back(std::to_string(flattenedCurves_) +
                               " curve segments flattened into straight segments");
  }

 private:
  static constexpr int kMaxUseDepth = 32;
  static constexpr std::size_t kMaxUseCopies = 1u << 20;
  std::unordered_map<std::string, const xmlNode*> ids_;
  int useDepth_ = 0;
  std::size_t useCopies_ = 0;
  static std::string localName(const xmlNode* node) {
    return reinterpret_cast<const char*>(node->name);
  }

  static std::optional<std::string> attribute(const xmlNode* node, const char* name) {
    xmlChar* value = xmlGetProp(node, reinterpret_cast<const xmlChar*>(name));
    if (!value) return std::nullopt;
    std::string out(reinterpret_cast<const char*>(value));
    xmlFree(value);
    return out;
  }

  static std::string valueOf(const Declarations& declarations, const char* name) {
    const auto found = declarations.find(name);
    return found == declarations.end() ? std::string() : found->second;
  }

  // Presentation attributes, then <style> rules by tag, class and tag.class, then style="...".
  Declarations declarationsOf(const xmlNode* node, const std::string& tag) const {
    Declarations out;
    for (const char* name :
         {"stroke", "stroke-opacity", "opacity", "display", "color", "transform"})
      if (const auto value = attribute(node, name)) out[name] = trim(*value);
    const auto apply = [&](const std::unordered_map<std::string, Declarations>& table,
                           const std::string& key) {
      if (const auto found = table.find(key); found != table.end())
        for (const auto& [name, value] : found->second) out[name] = value;
    };
    apply(rules_.byTag, lower(tag));
    if (const auto classes = attribute(node, "class")) {
      NumberScanner unused("");
      std::size_t start = 0;
      const std::string& list = *classes;
      while (start < list.size()) {
        while (start < list.size() && std::isspace(static_cast<unsigned char>(list[start])))
          ++start;
        std::size_t end = start;
        while (end < list.size() && !std::isspace(static_cast<unsigned char>(list[end]))) ++end;
        if (end > start) {
          const std::string name = list.substr(start, end - start);
          apply(rules_.byClass, name);
          apply(rules_.byTagClass, lower(tag) + "." + name);
        }
        start = end;
      }
    }
    if (const auto style = attribute(node, "style")) parseDeclarations(*style, out);
    return out;
  }

  Affine parseTransform(const xmlNode* node, const std::string& text) const {
    Affine result;
    std::size_t pos = 0;
    while (true) {
      while (pos < text.size() &&
             (std::isspace(static_cast<unsigned char>(text[pos])) || text[pos] == ','))
        ++pos;
      if (pos >= text.size()) return result;
      const std::size_t open = text.find('(', pos);
      const std::size_t close = open == std::string::npos ? open : text.find(')', open);
      if (close == std::string::npos) fail(node, "malformed transform " + quotedExcerpt(text));
      const std::string kind = trim(std::string_view(text).substr(pos, open - pos));
      NumberScanner scanner(std::string_view(text).substr(open + 1, close - open - 1));
      const bool angles = kind == "rotate" || kind == "skewX" || kind == "skewY" || kind == "skew";
      std::vector<double> v;
      while (!scanner.atEnd()) {
        const auto number = scanner.number();
        if (!number || v.size() == 6) fail(node, "malformed transform " + quotedExcerpt(text));
        // CSS's transform property writes its units: angles in deg, rad, grad or turn, lengths
        // in px (the user unit); the attribute writes none.
        const std::string unit = lower(std::string(scanner.skipUnit()));
        double scale = 1.0;
        if (unit.empty() || (unit == "px" && !angles) || (unit == "deg" && angles)) {
        } else if (unit == "rad" && angles) {
          scale = 180.0 / std::numbers::pi;
        } else if (unit == "grad" && angles) {
          scale = 0.9;
        } else if (unit == "turn" && angles) {
          scale = 360.0;
        } else {
          fail(node, "transform " + quotedExcerpt(kind) + " with the unit " + quotedExcerpt(unit) +
                         " (not read)");
        }
        v.push_back(*number * scale);
      }
      const auto need = [&](std::size_t low, std::size_t high) {
        if (v.size() < low || v.size() > high)
          fail(node, "transform " + quotedExcerpt(kind) + " with " + std::to_string(v.size()) +
                         " numbers");
      };
      Affine step;
      if (kind == "matrix") {
        need(6, 6);
        step = {v[0], v[1], v[2], v[3], v[4], v[5]};
      } else if (kind == "translate") {
        need(1, 2);
        step.e = v[0];
        step.f = v.size() > 1 ? v[1] : 0.0;
      } else if (kind == "scale") {
        need(1, 2);
        step.a = v[0];
        step.d = v.size() > 1 ? v[1] : v[0];
      } else if (kind == "rotate") {
        if (v.size() != 1 && v.size() != 3) need(1, 1);
        const double angle = v[0] * std::numbers::pi / 180.0;
        Affine rotation{std::cos(angle), std::sin(angle), -std::sin(angle), std::cos(angle), 0, 0};
        if (v.size() == 3)
          rotation = Affine{1, 0, 0, 1, v[1], v[2]} * rotation * Affine{1, 0, 0, 1, -v[1], -v[2]};
        step = rotation;
      } else if (kind == "translateX" || kind == "translateY") {  // CSS's own functions
        need(1, 1);
        (kind == "translateX" ? step.e : step.f) = v[0];
      } else if (kind == "scaleX" || kind == "scaleY") {
        need(1, 1);
        (kind == "scaleX" ? step.a : step.d) = v[0];
      } else if (kind == "skew") {
        need(1, 2);
        step.c = std::tan(v[0] * std::numbers::pi / 180.0);
        step.b = v.size() > 1 ? std::tan(v[1] * std::numbers::pi / 180.0) : 0.0;
      } else if (kind == "skewX") {
        need(1, 1);
        step.c = std::tan(v[0] * std::numbers::pi / 180.0);
      } else if (kind == "skewY") {
        need(1, 1);
        step.b = std::tan(v[0] * std::numbers::pi / 180.0);
      } else {
        fail(node, "unknown transform " + quotedExcerpt(kind));
      }
      result = result * step;
      pos = close + 1;
    }
  }

  double length(const xmlNode* node, const char* name) const {
    const auto value = attribute(node, name);
    if (!value || trim(*value).empty()) return 0.0;
    NumberScanner scanner(*value);
    const auto number = scanner.number();
    scanner.skipUnit();
    if (!number || !scanner.atEnd())
      fail(node, std::string(name) + " is not a number: " + quotedExcerpt(*value));
    return *number;
  }

  std::vector<glm::dvec2> points(const xmlNode* node) const {
    const std::string text = attribute(node, "points").value_or("");
    NumberScanner scanner(text);
    std::vector<glm::dvec2> out;
    while (!scanner.atEnd()) {
      const auto x = scanner.number();
      const auto y = x ? scanner.number() : std::nullopt;
      if (!x || !y) fail(node, "malformed points " + quotedExcerpt(text));
      out.emplace_back(*x, *y);
    }
    return out;
  }

  struct Polyline {
    std::vector<glm::dvec2> points;
    bool closed = false;
  };

  // Adds points along a curve given as a function of t in [0, 1], n pieces.
  template <typename Curve>
  void sampleCurve(Polyline& line, int pieces, const Curve& curve) {
    ++flattenedCurves_;
    for (int k = 1; k <= pieces; ++k) line.points.push_back(curve(static_cast<double>(k) / pieces));
  }

  static int piecesFor(double secondDifference, double polygonLength, double degreeFactor) {
    // Wang's bound: n = sqrt(degreeFactor * |second difference| / tolerance).
    const double tolerance = 0.002 * polygonLength;
    if (!(tolerance > 0.0)) return 1;
    const double n = std::ceil(std::sqrt(degreeFactor * secondDifference / tolerance));
    return static_cast<int>(std::clamp(n, 1.0, 64.0));
  }

  std::vector<Polyline> parsePath(const xmlNode* node) {
    const std::string text = attribute(node, "d").value_or("");
    NumberScanner scanner(text);
    std::vector<Polyline> out;
    glm::dvec2 current(0.0), start(0.0), lastControl(0.0);
    char previous = 0;
    char command = 0;
    const auto bad = [&](const std::string& what) {
      fail(node, "malformed path data (" + what + "): " + quotedExcerpt(text));
    };
    const auto number = [&]() {
      const auto value = scanner.number();
      if (!value) bad("a number expected");
      return *value;
    };
    const auto pointAt = [&](bool relative) {
      const double x = number();
      const double y = number();
      return relative ? current + glm::dvec2(x, y) : glm::dvec2(x, y);
    };
    const auto lineTo = [&](glm::dvec2 p) {
      if (out.empty()) out.push_back({{current}, false});
      out.back().points.push_back(p);
      current = p;
    };
    while (!scanner.atEnd()) {
      const char ch = scanner.peek();
      if (std::isalpha(static_cast<unsigned char>(ch))) {
        command = ch;
        scanner.advance();
      } else if (command == 0) {
        bad("no command first");
      } else if (command == 'M') {
        command = 'L';  // more pairs after a moveto are linetos
      } else if (command == 'm') {
        command = 'l';
      } else if (command == 'Z' || command == 'z') {
        bad("numbers after Z");
      }
      const bool relative = std::islower(static_cast<unsigned char>(command));
      switch (std::toupper(static_cast<unsigned char>(command))) {
        case 'M': {
          // A relative moveto first in a path is absolute (SVG 1.1, 8.3.2).
          current = pointAt(relative && previous != 0);
          start = current;
          out.push_back({{current}, false});
          break;
        }
        case 'L':
          lineTo(pointAt(relative));
          break;
        case 'H': {
          const double x = number();
          lineTo({relative ? current.x + x : x, current.y});
          break;
        }
        case 'V': {
          const double y = number();
          lineTo({current.x, relative ? current.y + y : y});
          break;
        }
        case 'Z':
          if (!out.empty()) out.back().closed = true;
          current = start;
          out.push_back({{current}, false});
          break;
        case 'C':
        case 'S': {
          const glm::dvec2 p0 = current;
          glm::dvec2 p1;
          if (std::toupper(static_cast<unsigned char>(command)) == 'C') {
            p1 = pointAt(relative);
          } else {
            const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(previous)));
            p1 = (up == 'C' || up == 'S') ? 2.0 * p0 - lastControl : p0;
          }
          const glm::dvec2 p2 = pointAt(relative), p3 = pointAt(relative);
          const double second =
              std::max(glm::length(p0 - 2.0 * p1 + p2), glm::length(p1 - 2.0 * p2 + p3));
          const double polygon = glm::length(p1 - p0) + glm::length(p2 - p1) + glm::length(p3 - p2);
          if (out.empty()) out.push_back({{current}, false});
          sampleCurve(out.back(), piecesFor(second, polygon, 0.75), [&](double t) {
            const double s = 1.0 - t;
            return s * s * s * p0 + 3.0 * s * s * t * p1 + 3.0 * s * t * t * p2 + t * t * t * p3;
          });
          current = p3;
          lastControl = p2;
          break;
        }
        case 'Q':
        case 'T': {
          const glm::dvec2 p0 = current;
          glm::dvec2 p1;
          if (std::toupper(static_cast<unsigned char>(command)) == 'Q') {
            p1 = pointAt(relative);
          } else {
            const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(previous)));
            p1 = (up == 'Q' || up == 'T') ? 2.0 * p0 - lastControl : p0;
          }
          const glm::dvec2 p2 = pointAt(relative);
          const double second = glm::length(p0 - 2.0 * p1 + p2);
          const double polygon = glm::length(p1 - p0) + glm::length(p2 - p1);
          if (out.empty()) out.push_back({{current}, false});
          sampleCurve(out.back(), piecesFor(second, polygon, 0.25), [&](double t) {
            const double s = 1.0 - t;
            return s * s * p0 + 2.0 * s * t * p1 + t * t * p2;
          });
          current = p2;
          lastControl = p1;
          break;
        }
        case 'A': {
          double rx = std::abs(number()), ry = std::abs(number());
          const double rotation = number() * std::numbers::pi / 180.0;
          const auto large = scanner.flag();
          const auto sweep = large ? scanner.flag() : std::nullopt;
          if (!large || !sweep) bad("an arc flag expected");
          const glm::dvec2 p0 = current, p1 = pointAt(relative);
          if (out.empty()) out.push_back({{current}, false});
          if (rx == 0.0 || ry == 0.0 || p0 == p1) {
            lineTo(p1);
            break;
          }
          // Endpoint to centre parameterisation (SVG 1.1, F.6.5).
          const double cs = std::cos(rotation), sn = std::sin(rotation);
          const glm::dvec2 h = (p0 - p1) * 0.5;
          const glm::dvec2 q(cs * h.x + sn * h.y, -sn * h.x + cs * h.y);
          const double lambda = q.x * q.x / (rx * rx) + q.y * q.y / (ry * ry);
          if (lambda > 1.0) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);
          const double num = rx * rx * ry * ry - rx * rx * q.y * q.y - ry * ry * q.x * q.x;
          const double den = rx * rx * q.y * q.y + ry * ry * q.x * q.x;
          double factor = std::sqrt(std::max(0.0, num / den));
          if (*large == *sweep) factor = -factor;
          const glm::dvec2 cq(factor * rx * q.y / ry, -factor * ry * q.x / rx);
          const glm::dvec2 centre =
              glm::dvec2(cs * cq.x - sn * cq.y, sn * cq.x + cs * cq.y) + (p0 + p1) * 0.5;
          const double theta0 = std::atan2((q.y - cq.y) / ry, (q.x - cq.x) / rx);
          double delta = std::atan2((-q.y - cq.y) / ry, (-q.x - cq.x) / rx) - theta0;
          if (*sweep == 0.0 && delta > 0) delta -= 2 * std::numbers::pi;
          if (*sweep == 1.0 && delta < 0) delta += 2 * std::numbers::pi;
          const int pieces = static_cast<int>(
              std::clamp(std::ceil(std::abs(delta) / (std::numbers::pi / 24)), 1.0, 64.0));
          sampleCurve(out.back(), pieces, [&](double t) {
            if (t >= 1.0) return p1;
            const double angle = theta0 + delta * t;
            const glm::dvec2 e(rx * std::cos(angle), ry * std::sin(angle));
            return centre + glm::dvec2(cs * e.x - sn * e.y, sn * e.x + cs * e.y);
          });
          current = p1;
          break;
        }
        default:
          bad("unknown command " + std::string(1, command));
      }
      if (!std::isfinite(current.x) || !std::isfinite(current.y)) bad("a point not finite");
      previous = command;
    }
    return out;
  }

  void shape(const xmlNode* node, const std::string& tag, const Inherited& here,
             const Declarations& style) {
    if (here.stroke.empty() || lower(here.stroke) == "none") {
      ++noStroke_;
      return;
    }
    bool namedGreen = false;
    double colourAlpha = 1.0;
    // currentColor is the element's color property (inherited), as a browser draws it.
    const std::string& stroke = lower(trim(here.stroke)) == "currentcolor" && !here.color.empty()
                                    ? here.color
                                    : here.stroke;
    const auto rgb = parseColour(stroke, namedGreen, colourAlpha);
    const auto assignment = rgb ? assignmentForColour(*rgb, namedGreen) : std::nullopt;
    if (!assignment) {
      ++unknownColours_[lower(trim(stroke))];
      return;
    }
    std::vector<Polyline> lines;
    if (tag == "line") {
      lines.push_back(
          {{{length(node, "x1"), length(node, "y1")}, {length(node, "x2"), length(node, "y2")}},
           false});
    } else if (tag == "rect") {
      const double x = length(node, "x"), y = length(node, "y");
      const double w = length(node, "width"), h = length(node, "height");
      if (w < 0 || h < 0) fail(node, "a rect of negative size");
      lines.push_back({{{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}}, true});
    } else if (tag == "circle" || tag == "ellipse") {
      const double cx = length(node, "cx"), cy = length(node, "cy");
      const double rx = length(node, tag == "circle" ? "r" : "rx");
      const double ry = tag == "circle" ? rx : length(node, "ry");
      if (rx < 0 || ry < 0) fail(node, "a " + tag + " of negative radius");
      Polyline loop;
      loop.closed = true;
      constexpr int kPieces = 64;
      for (int k = 0; k < kPieces; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / kPieces;
        loop.points.emplace_back(cx + rx * std::cos(angle), cy + ry * std::sin(angle));
      }
      ++flattenedCurves_;
      lines.push_back(std::move(loop));
    } else if (tag == "polyline" || tag == "polygon") {
      lines.push_back({points(node), tag == "polygon"});
    } else {
      lines = parsePath(node);
    }
    // A colour's alpha is opacity as the eye sees it, as stroke-opacity is: both set the angle.
    double opacity = colourAlpha;
    for (const std::string& text : {valueOf(style, "opacity"), here.strokeOpacity}) {
      if (text.empty()) continue;
      NumberScanner scanner(text);
      auto value = scanner.number();
      if (!value) fail(node, "opacity is not a number: " + quotedExcerpt(text));
      if (scanner.peek() == '%') *value /= 100.0;
      opacity *= std::clamp(*value, 0.0, 1.0);
    }
    CreaseLine line;
    line.assignment = *assignment;
    if (*assignment == CreaseAssignment::Mountain) line.foldAngleDegrees = -180.0 * opacity;
    if (*assignment == CreaseAssignment::Valley) line.foldAngleDegrees = 180.0 * opacity;
    const std::string name = "line " + std::to_string(xmlGetLineNo(node)) + " (<" + tag + ">)";
    for (const Polyline& polyline : lines) {
      const std::size_t n = polyline.points.size();
      for (std::size_t k = 0; k + 1 < n + (polyline.closed && n > 2 ? 1 : 0); ++k) {
        const glm::dvec2 p = here.transform(polyline.points[k]);
        const glm::dvec2 q = here.transform(polyline.points[(k + 1) % n]);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(q.x) ||
            !std::isfinite(q.y))
          fail(node, "a point is not finite after its transform");
        if (drawing_.lines.size() >= kMaxCreasePatternEdges)
          fail(node, "more than " + std::to_string(kMaxCreasePatternEdges) +
                         " line segments in the file");
        line.a = static_cast<std::uint32_t>(drawing_.vertices.size());
        line.b = line.a + 1;
        // y down on screen: negated, so the pattern keeps its look seen from +z.
        drawing_.vertices.emplace_back(p.x, -p.y);
        drawing_.vertices.emplace_back(q.x, -q.y);
        drawing_.lines.push_back(line);
        drawing_.lineNames.push_back(name);
      }
    }
  }

  std::string name_;
  CreaseDrawing& drawing_;
  CssRules rules_;
  std::map<std::string, std::size_t> unknownColours_, ignoredElements_;
  std::size_t noStroke_ = 0, flattenedCurves_ = 0;
};

// SVG's absolute units in px (CSS Values 3: 96 px to the inch).
std::optional<double> pxPerUnit(std::string_view unit) {
  const std::string u = lower(unit);
  if (u.empty() || u == "px") return 1.0;
  if (u == "in") return 96.0;
  if (u == "cm") return 96.0 / 2.54;
  if (u == "mm") return 96.0 / 25.4;
  if (u == "q") return 96.0 / 101.6;
  if (u == "pt") return 96.0 / 72.0;
  if (u == "pc") return 16.0;
  return std::nullopt;  // %, em, ex, vw: relative to a viewport the file does not fix
}

struct RootLength {
  double px = 0.0;  // > 0 when given in an absolute unit
  std::string unit;
};

// Units relative to a viewport or a font the file does not fix: no size, as documented.
bool relativeUnit(std::string_view unit) {
  for (const char* relative : {"%", "em", "ex", "ch", "rem", "vw", "vh", "vmin", "vmax"})
    if (unit == relative) return true;
  return false;
}

// The root's width or height in px; 0 when absent, relative or malformed. A malformed value (not
// a number, not positive, an unknown unit) is ignored, as a browser and Origami Simulator ignore
// it, with a note naming the attribute and its value, so the size it falls back to is not silent.
RootLength rootLength(const xmlNode* root, const char* name, std::vector<std::string>& notes) {
  RootLength out;
  xmlChar* value = xmlGetProp(root, reinterpret_cast<const xmlChar*>(name));
  if (!value) return out;
  const std::string text = trim(reinterpret_cast<const char*>(value));
  xmlFree(value);
  const auto ignored = [&](const std::string& why) {
    notes.push_back(std::string("<svg ") + name + "=" + quotedExcerpt(text, 40) + ">: " + why +
                    "; ignored (the size then comes from the other attribute or the default, "
                    "96 px per inch)");
  };
  NumberScanner scanner(text);
  const auto number = scanner.number();
  if (!number) {
    ignored("not a length");
    return out;
  }
  out.unit = lower(trim(std::string_view(text).substr(scanner.position())));
  if (relativeUnit(out.unit)) return out;  // no size of its own (the size line says so)
  const auto factor = pxPerUnit(out.unit);
  if (!factor) {
    ignored("unknown unit " + quotedExcerpt(out.unit, 20) + " (mm, cm, Q, in, pt, pc or px)");
    return out;
  }
  if (!(*number > 0.0)) {
    ignored("not a positive length");
    return out;
  }
  out.px = *number * *factor;
  return out;
}

// One user unit of the drawing in metres, as a browser sizes the root (SVG 1.1, 7.7-7.8): width
// and height in px (96 to the inch; unitless is px) over the viewBox's, the smaller of the two
// when they differ (preserveAspectRatio's default, meet); one of them alone scales both; no
// viewBox: a user unit is a px. With neither size given the drawing has no size of its own, and
// a user unit is taken as a px too (the stated default, docs/formats.md).
double svgUserUnitMetres(const xmlNode* root, std::string& source,
                         std::vector<std::string>& notes) {
  constexpr double kMetresPerPx = 0.0254 / 96.0;
  const RootLength width = rootLength(root, "width", notes),
                   height = rootLength(root, "height", notes);
  std::array<double, 4> box{};
  bool hasBox = false;
  xmlChar* value = xmlGetProp(root, reinterpret_cast<const xmlChar*>("viewBox"));
  if (value) {
    NumberScanner scanner(reinterpret_cast<const char*>(value));
    hasBox = true;
    for (double& v : box) {
      const auto number = scanner.number();
      hasBox = hasBox && number.has_value();
      v = number.value_or(0.0);
    }
    hasBox = hasBox && scanner.atEnd() && box[2] > 0.0 && box[3] > 0.0;
    xmlFree(value);
  }
  const auto named = [](const RootLength& a, const RootLength& b) {
    const std::string& unit = a.px > 0.0 ? a.unit : b.unit;
    return unit.empty()   ? std::string("unitless, read as px at 96 per inch")
           : unit == "px" ? std::string("in px at 96 per inch")
                          : "in " + unit;
  };
  if (width.px <= 0.0 && height.px <= 0.0) {
    source = "no width or height in an absolute unit: one user unit read as one px, 96 per inch";
    return kMetresPerPx;
  }
  if (!hasBox) {
    source = "no viewBox: one user unit is one px, 96 per inch";
    return kMetresPerPx;
  }
  const double sx = width.px > 0.0 ? width.px / box[2] : height.px / box[3];
  const double sy = height.px > 0.0 ? height.px / box[3] : sx;
  source = "width and height " + named(width, height) + " over the viewBox";
  return std::min(sx, sy) * kMetresPerPx;
}

struct XmlDocument {
  xmlParserCtxtPtr context = nullptr;
  xmlDocPtr document = nullptr;
  ~XmlDocument() {
    if (document) xmlFreeDoc(document);
    if (context) xmlFreeParserCtxt(context);
  }
};

// The longest run of bytes between markup or quote characters: an attribute value's or a text's
// length, near enough.
std::size_t longestToken(std::string_view text) {
  std::size_t longest = 0, run = 0;
  for (const char c : text) {
    run = (c == '<' || c == '>' || c == '"' || c == '\'') ? 0 : run + 1;
    longest = std::max(longest, run);
  }
  return longest;
}

}  // namespace

CreasePattern readSvgCreasePatternText(std::string_view text, std::string_view name,
                                       const SvgReadOptions& options) {
  const std::string prefix(name);
  try {
    if (text.size() > kMaxCreasePatternBytes)
      throw CreasePatternError(
          tooLarge(prefix, text.size(), kMaxCreasePatternBytes, "crease pattern"));
    XmlDocument xml;
    xml.context = xmlNewParserCtxt();
    if (!xml.context) throw std::bad_alloc();
    // No network, no external entities or DTDs, no entity substitution; libxml2's own limits on
    // depth and entity expansion stay on (no XML_PARSE_HUGE); line numbers past 65535 stay exact.
    xml.document = xmlCtxtReadMemory(
        xml.context, text.data(), static_cast<int>(text.size()), prefix.c_str(), nullptr,
        XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING | XML_PARSE_BIG_LINES);
    if (!xml.document) {
      const xmlError* error = xmlCtxtGetLastError(xml.context);
      std::string message = error && error->message ? trim(error->message) : "unreadable";
      // libxml2's own limits (no XML_PARSE_HUGE, above): one attribute or text over 10,000,000
      // bytes, or as much read ahead through long attributes, end in a message about the
      // input's end or a "Huge input lookup"; name the limit instead.
      const std::size_t token = longestToken(text);
      if (token > kMaxSvgTokenBytes || message.find("Huge input lookup") != std::string::npos)
        throw CreasePatternError(prefix + ": more than the XML reader takes (" +
                                 std::to_string(kMaxSvgTokenBytes) +
                                 " bytes in one attribute or text, or read ahead through long "
                                 "ones; the longest here " +
                                 std::to_string(token) + " bytes): split long paths");
      throw CreasePatternError(prefix + ": not valid XML at line " +
                               std::to_string(error ? error->line : 0) + ": " +
                               quotedExcerpt(message, 100));
    }
    const xmlNode* root = xmlDocGetRootElement(xml.document);
    if (!root || std::string_view(reinterpret_cast<const char*>(root->name)) != "svg")
      throw CreasePatternError(prefix + ": not an SVG file (its root element is not <svg>)");
    CreaseDrawing drawing;
    SvgReader reader(prefix, drawing);
    reader.collectStyles(root);
    reader.walk(root, Inherited{});
    reader.finish();
    if (drawing.lines.empty())
      throw CreasePatternError(
          prefix +
          ": no lines of a crease colour (black border, red mountain, blue valley, "
          "green cut, yellow facet, magenta hinge)" +
          (drawing.notes.empty() ? std::string() : "; " + drawing.notes.front()));
    PlanarizeOptions planar;
    planar.strict = false;
    planar.noteCoincidentPoints = false;
    planar.relativeSnap = options.relativeSnap;
    planarize(drawing, planar);
    TriangulateOptions triangulate;
    triangulate.dropLinesWithoutFace = true;
    triangulate.innerBorderAsHinge = true;
    CreasePattern pattern = triangulateCreaseDrawing(drawing, triangulate);
    pattern.metresPerUnit = svgUserUnitMetres(root, pattern.unitSource, pattern.notes);
    return pattern;
  } catch (const CreasePatternError& error) {
    const std::string message = error.what();
    if (message.rfind(prefix + ": ", 0) == 0) throw;
    throw CreasePatternError(prefix + ": " + message);
  } catch (const std::bad_alloc&) {
    throw CreasePatternError(prefix + ": out of memory reading it");
  }
}

CreasePattern readSvgCreasePattern(const std::filesystem::path& path,
                                   const SvgReadOptions& options) {
  const std::string text = readWholeFile(path, kMaxCreasePatternBytes, "crease pattern");
  return readSvgCreasePatternText(text, path.string(), options);
}

}  // namespace curvefold
