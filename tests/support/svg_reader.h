// svg_reader.h — reads back the geometry of the SVG pictures conformesh writes (embedding/layout/layout_picture.h):
// the root's viewBox, every <polygon>/<polyline> with its points, fill and stroke (and the stroke of the enclosing
// <g>), every <circle>. A tag scanner for this flat, attribute-only SVG, not a general XML parser. Throws
// std::runtime_error naming what it cannot read.
#pragma once

#include <array>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace conformesh::testing {

struct SvgShape {
  std::string tag;                                // polygon or polyline
  std::vector<std::array<double, 2>> points;      // in the viewBox's coordinates (y down)
  std::string fill, stroke, groupStroke;          // "" when absent
};
struct SvgCircle {
  double cx = 0, cy = 0, r = 0;
};
struct SvgPicture {
  std::array<double, 4> viewBox{};  // min-x, min-y, width, height
  std::vector<SvgShape> shapes;
  std::vector<SvgCircle> circles;
};

inline SvgPicture readSvg(const std::string& text) {
  auto fail = [](const std::string& what) { throw std::runtime_error("svg: " + what); };
  auto attributes = [&](const std::string& tag) {
    std::map<std::string, std::string> a;
    std::size_t p = tag.find_first_of(" \t\n");
    while (p != std::string::npos) {
      const std::size_t eq = tag.find('=', p);
      if (eq == std::string::npos) break;
      const std::size_t nameStart = tag.find_first_not_of(" \t\n", p);
      if (tag[eq + 1] != '"') fail("unquoted attribute in <" + tag.substr(0, 40) + ">");
      const std::size_t close = tag.find('"', eq + 2);
      if (close == std::string::npos) fail("unterminated attribute in <" + tag.substr(0, 40) + ">");
      a[tag.substr(nameStart, eq - nameStart)] = tag.substr(eq + 2, close - eq - 2);
      p = close + 1;
    }
    return a;
  };
  auto number = [&](const std::string& s) {
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0') fail("'" + s + "' is not a number");
    return x;
  };
  SvgPicture pic;
  bool root = false;
  std::vector<std::string> groupStrokes;
  for (std::size_t open = text.find('<'); open != std::string::npos; open = text.find('<', open + 1)) {
    const std::size_t close = text.find('>', open);
    if (close == std::string::npos) fail("unterminated tag");
    std::string tag = text.substr(open + 1, close - open - 1);
    if (!tag.empty() && tag.back() == '/') tag.pop_back();
    const std::string name = tag.substr(0, tag.find_first_of(" \t\n"));
    if (name == "svg") {
      const auto a = attributes(tag);
      if (!a.count("viewBox")) fail("<svg> without viewBox");
      std::istringstream v(a.at("viewBox"));
      for (double& x : pic.viewBox)
        if (!(v >> x)) fail("bad viewBox '" + a.at("viewBox") + "'");
      root = true;
    } else if (name == "g") {
      const auto a = attributes(tag);
      groupStrokes.push_back(a.count("stroke") ? a.at("stroke") : "");
    } else if (name == "/g") {
      if (groupStrokes.empty()) fail("</g> without <g>");
      groupStrokes.pop_back();
    } else if (name == "polygon" || name == "polyline") {
      const auto a = attributes(tag);
      SvgShape s;
      s.tag = name;
      s.fill = a.count("fill") ? a.at("fill") : "";
      s.stroke = a.count("stroke") ? a.at("stroke") : "";
      s.groupStroke = groupStrokes.empty() ? "" : groupStrokes.back();
      if (!a.count("points")) fail("<" + name + "> without points");
      std::istringstream pts(a.at("points"));
      for (std::string pair; pts >> pair;) {
        const std::size_t comma = pair.find(',');
        if (comma == std::string::npos) fail("point '" + pair + "' is not x,y");
        s.points.push_back({number(pair.substr(0, comma)), number(pair.substr(comma + 1))});
      }
      pic.shapes.push_back(s);
    } else if (name == "circle") {
      const auto a = attributes(tag);
      for (const char* k : {"cx", "cy", "r"})
        if (!a.count(k)) fail(std::string("<circle> without ") + k);
      pic.circles.push_back({number(a.at("cx")), number(a.at("cy")), number(a.at("r"))});
    }
  }
  if (!root) fail("no <svg> element");
  if (!groupStrokes.empty()) fail("unclosed <g>");
  return pic;
}

}  // namespace conformesh::testing
