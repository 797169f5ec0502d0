// vtk_reader.h — reads back the legacy ASCII VTK POLYDATA that conformesh writes (intrinsic/io/vtk_writer.h), for
// tests that compare it with the mesh of the same run: the points, the polygons and every POINT_DATA / CELL_DATA
// scalar array, each array's length checked against the count its section announces. Independent of the writer: it
// follows the format's text (VTK's "File Formats" document, legacy format), not conformesh's code. Throws
// std::runtime_error naming what is wrong.
#pragma once

#include <array>
#include <cstdlib>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace conformesh::testing {

struct VtkPolyData {
  std::string version, title, encoding, dataset;
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<int>> polygons;
  std::map<std::string, std::vector<double>> pointData, cellData;  // SCALARS arrays with one component
};

inline VtkPolyData readVtkPolyData(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  auto fail = [&](const std::string& what) { throw std::runtime_error(path + ": " + what); };
  VtkPolyData d;
  if (!std::getline(in, d.version) || d.version.rfind("# vtk DataFile Version ", 0) != 0) fail("no VTK header line");
  if (!std::getline(in, d.title)) fail("no title line");
  std::string word;
  auto token = [&](const char* what) {
    if (!(in >> word)) fail(std::string("file ends before ") + what);
    return word;
  };
  // Numbers through strtod, which reads "nan" and "inf" as the writer spells them (operator>> does not).
  auto number = [&](const char* what) {
    const std::string t = token(what);
    char* end = nullptr;
    const double x = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || *end != '\0') fail(std::string("'") + t + "' is not a number (" + what + ")");
    return x;
  };
  auto count = [&](const char* what) {
    const double x = number(what);
    if (x < 0 || x != static_cast<double>(static_cast<long>(x))) fail(std::string("bad count (") + what + ")");
    return static_cast<long>(x);
  };
  d.encoding = token("the encoding");
  if (d.encoding != "ASCII") fail("encoding " + d.encoding + ", expected ASCII");
  if (token("DATASET") != "DATASET") fail("expected DATASET, found " + word);
  d.dataset = token("the dataset type");
  if (d.dataset != "POLYDATA") fail("dataset " + d.dataset + ", expected POLYDATA");
  std::map<std::string, std::vector<double>>* attributes = nullptr;
  long attributeCount = 0;
  bool havePoints = false, havePolygons = false;
  while (in >> word) {
    if (word == "POINTS") {
      const long n = count("the point count");
      token("the point type");
      d.points.resize(static_cast<std::size_t>(n));
      for (auto& p : d.points)
        for (double& x : p) x = number("a point coordinate");
      havePoints = true;
    } else if (word == "POLYGONS") {
      const long n = count("the polygon count"), size = count("the polygon list size");
      long read = 0;
      for (long f = 0; f < n; ++f) {
        const long k = count("a polygon's vertex count");
        std::vector<int> poly;
        for (long i = 0; i < k; ++i) {
          const long v = count("a polygon's vertex");
          if (v >= static_cast<long>(d.points.size())) fail("polygon " + std::to_string(f) + " refers to point " +
                                                            std::to_string(v) + " of " +
                                                            std::to_string(d.points.size()));
          poly.push_back(static_cast<int>(v));
        }
        read += 1 + k;
        d.polygons.push_back(poly);
      }
      if (read != size) fail("POLYGONS announces " + std::to_string(size) + " numbers, found " + std::to_string(read));
      havePolygons = true;
    } else if (word == "POINT_DATA" || word == "CELL_DATA") {
      const bool onPoints = word == "POINT_DATA";
      const std::string section = word;
      attributeCount = count("the attribute count");
      const long expected = static_cast<long>(onPoints ? d.points.size() : d.polygons.size());
      if (attributeCount != expected)
        fail(section + " " + std::to_string(attributeCount) + ", expected " + std::to_string(expected));
      attributes = onPoints ? &d.pointData : &d.cellData;
    } else if (word == "SCALARS") {
      if (!attributes) fail("SCALARS outside POINT_DATA / CELL_DATA");
      const std::string name = token("the array name");
      token("the array type");
      // The component count is optional; LOOKUP_TABLE is required.
      std::string next = token("LOOKUP_TABLE");
      if (next != "LOOKUP_TABLE") {
        if (next != "1") fail("array " + name + " has " + next + " components, expected 1");
        next = token("LOOKUP_TABLE");
      }
      if (next != "LOOKUP_TABLE") fail("array " + name + ": expected LOOKUP_TABLE, found " + next);
      token("the lookup table name");
      if (attributes->count(name)) fail("array " + name + " appears twice");
      std::vector<double>& values = (*attributes)[name];
      for (long i = 0; i < attributeCount; ++i) values.push_back(number(("array " + name).c_str()));
    } else {
      fail("unexpected keyword '" + word + "'");
    }
  }
  if (!havePoints) fail("no POINTS section");
  if (!havePolygons) fail("no POLYGONS section");
  return d;
}

}  // namespace conformesh::testing
