// ply_io.cpp — Stanford PLY in all three encodings (ascii, binary_little_endian, binary_big_endian): the reader
// (parsePly) and the serializer behind writeMesh(".ply").
//
// Read: `element vertex` (x y z optional — a metric-only mesh has none — and every other scalar property kept by name),
// `element face` (list `vertex_indices` or `vertex_index`, optional list `edge_index` of corner edge ids for
// Δ-complexes), `element tristrips` (list `vertex_indices`, strips separated by -1), `element edge` (vertex1 vertex2 length, other scalars kept by name); every other element and property
// is skipped, lists included, in every encoding. `comment geometry <name>` sets the background. Binary data is read
// from memory with memcpy; every count is checked against the bytes that remain before anything is allocated. Errors
// name the element: "FILE:LINE: ..." in the header and ASCII data, "FILE: face 12: ..." in binary data. docs/formats.md
// is the reference.
#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "io/mesh_io_internal.h"
#include "io/text_scanner.h"

namespace conformesh::intrinsic {

namespace {

using detail::quoteToken;

// === scalar types

enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

int typeSize(PlyType t) {
  static constexpr int sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[static_cast<int>(t)];
}
bool isIntegerType(PlyType t) {
  return t != PlyType::Float32 && t != PlyType::Float64;
}
const char* typeName(PlyType t) {
  static const char* names[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"};
  return names[static_cast<int>(t)];
}
bool typeFromName(std::string_view s, PlyType& t) {
  static const std::pair<std::string_view, PlyType> table[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [name, type] : table)
    if (s == name) {
      t = type;
      return true;
    }
  return false;
}
void integerRange(PlyType t, long long& lo, long long& hi) {
  switch (t) {
    case PlyType::Int8:
      lo = INT8_MIN, hi = INT8_MAX;
      return;
    case PlyType::UInt8:
      lo = 0, hi = UINT8_MAX;
      return;
    case PlyType::Int16:
      lo = INT16_MIN, hi = INT16_MAX;
      return;
    case PlyType::UInt16:
      lo = 0, hi = UINT16_MAX;
      return;
    case PlyType::Int32:
      lo = INT32_MIN, hi = INT32_MAX;
      return;
    default:
      lo = 0, hi = UINT32_MAX;
      return;
  }
}

// === header

struct PlyProperty {
  std::string name;
  bool isList = false;
  PlyType type = PlyType::Float64;  // the scalar type, or a list's item type
  PlyType countType = PlyType::UInt8;
};

struct PlyElement {
  std::string name;
  long long count = 0;
  int line = 0;
  std::vector<PlyProperty> properties;

  int find(std::string_view prop) const {
    for (std::size_t i = 0; i < properties.size(); ++i)
      if (properties[i].name == prop) return static_cast<int>(i);
    return -1;
  }
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  std::size_t dataOffset = 0;
  int dataLine = 0;  // line number of the first data byte (ASCII)
};

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t begin = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > begin) words.push_back(line.substr(begin, i - begin));
  }
  return words;
}

PlyHeader parseHeader(const std::string& bytes, MeshData& data) {
  const std::string& source = data.source;
  PlyHeader h;
  std::size_t pos = 0;
  int line = 0;
  int geometryLine = 0;
  bool haveFormat = false;
  // Hash sets keep duplicate detection linear in the header size, however many properties a hostile header lists.
  std::unordered_map<std::string, int> elementLines;
  std::unordered_set<std::string> propertyNames;
  const auto fail = [&](const std::string& what) {
    throw InputError(source + ":" + std::to_string(line) + ": " + what);
  };
  if (bytes.empty()) {
    line = 1;
    fail("empty file; expected the magic line 'ply'");
  }
  for (;;) {
    if (pos >= bytes.size()) fail("end of file inside the header; expected 'end_header'");
    ++line;
    const std::size_t nl = bytes.find('\n', pos);
    const std::size_t lineEnd = nl == std::string::npos ? bytes.size() : nl;
    std::string_view text(bytes.data() + pos, lineEnd - pos);
    pos = nl == std::string::npos ? bytes.size() : nl + 1;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    if (line == 1) {
      if (text != "ply") fail("expected the magic line 'ply', found " + quoteToken(text));
      continue;
    }
    const std::vector<std::string_view> w = splitWords(text);
    if (w.empty()) continue;
    if (w[0] == "comment") {
      std::string_view body = text.substr(text.find("comment") + 7);
      while (!body.empty() && (body.front() == ' ' || body.front() == '\t')) body.remove_prefix(1);
      while (!body.empty() && (body.back() == ' ' || body.back() == '\t')) body.remove_suffix(1);
      const std::string where = source + ":" + std::to_string(line);
      Background g = Background::Euclidean;
      if (detail::parseGeometryComment(body, where, g)) {
        if (geometryLine != 0 && g != data.background)
          fail("comment geometry " + toString(g) + " contradicts geometry " + toString(data.background) +
               " declared on line " + std::to_string(geometryLine));
        data.background = g;
        geometryLine = line;
      } else {
        data.comments.emplace_back(body);
      }
    } else if (w[0] == "obj_info") {
      continue;  // free text by definition; nothing to interpret
    } else if (w[0] == "format") {
      if (haveFormat) fail("second 'format' line");
      if (w.size() != 3)
        fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0', found " + quoteToken(text));
      if (w[1] == "ascii") {
        h.encoding = PlyEncoding::Ascii;
      } else if (w[1] == "binary_little_endian") {
        h.encoding = PlyEncoding::BinaryLittleEndian;
      } else if (w[1] == "binary_big_endian") {
        h.encoding = PlyEncoding::BinaryBigEndian;
      } else {
        fail("expected the encoding ascii, binary_little_endian or binary_big_endian, found " + quoteToken(w[1]));
      }
      if (w[2] != "1.0") fail("expected PLY version 1.0, found " + quoteToken(w[2]));
      haveFormat = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) fail("expected 'element <name> <count>', found " + quoteToken(text));
      PlyElement el;
      el.name = std::string(w[1]);
      el.line = line;
      if (!detail::parseInteger(w[2], el.count))
        fail("element " + el.name + ": expected its count (an integer), found " + quoteToken(w[2]));
      if (el.count < 0) fail("element " + el.name + ": negative count " + std::to_string(el.count));
      const auto [it, isNew] = elementLines.emplace(el.name, line);
      if (!isNew) fail("second 'element " + el.name + "' (first on line " + std::to_string(it->second) + ")");
      propertyNames.clear();
      h.elements.push_back(std::move(el));
    } else if (w[0] == "property") {
      if (h.elements.empty()) fail("'property' before any 'element' line");
      PlyElement& el = h.elements.back();
      PlyProperty p;
      if (w.size() >= 2 && w[1] == "list") {
        if (w.size() != 5) fail("expected 'property list <count type> <item type> <name>', found " + quoteToken(text));
        if (!typeFromName(w[2], p.countType)) fail("unknown list count type " + quoteToken(w[2]));
        if (!isIntegerType(p.countType)) fail("list count type must be an integer type, found " + quoteToken(w[2]));
        if (!typeFromName(w[3], p.type)) fail("unknown list item type " + quoteToken(w[3]));
        p.isList = true;
        p.name = std::string(w[4]);
      } else {
        if (w.size() != 3) fail("expected 'property <type> <name>', found " + quoteToken(text));
        if (!typeFromName(w[1], p.type))
          fail("unknown property type " + quoteToken(w[1]) +
               "; expected char uchar short ushort int uint float double or int8 ... float64");
        p.name = std::string(w[2]);
      }
      if (!propertyNames.insert(p.name).second) fail("element " + el.name + " has a second property '" + p.name + "'");
      el.properties.push_back(std::move(p));
    } else if (w[0] == "end_header") {
      if (w.size() != 1) fail("expected 'end_header', found " + quoteToken(text));
      if (!haveFormat) fail("'end_header' before any 'format' line");
      h.dataOffset = pos;
      h.dataLine = line + 1;
      return h;
    } else {
      fail("expected a header line (format, comment, obj_info, element, property, end_header), found " +
           quoteToken(text));
    }
  }
}

// Rejects element counts the remaining bytes cannot hold, before anything is allocated: a binary element needs at
// least the sum of its scalar sizes and list-count sizes; an ASCII one at least one character and one separator per
// value (the last separator may be missing).
void checkCountsAgainstSize(const PlyHeader& h, std::size_t totalBytes, const std::string& source) {
  const long long remaining = static_cast<long long>(totalBytes - h.dataOffset);
  const bool binary = h.encoding != PlyEncoding::Ascii;
  long long needed = 0;
  for (const PlyElement& el : h.elements) {
    long long minSize = 0;
    for (const PlyProperty& p : el.properties) minSize += binary ? typeSize(p.isList ? p.countType : p.type) : 2;
    if (minSize == 0 || el.count == 0) continue;
    if (el.count > (remaining + 1) / minSize || needed + el.count * minSize > remaining + (binary ? 0 : 1))
      throw InputError(source + ":" + std::to_string(el.line) + ": element " + el.name + " declares " +
                       std::to_string(el.count) + " elements of at least " + std::to_string(minSize) +
                       " bytes each, but only " + std::to_string(std::max(0LL, remaining - needed)) +
                       " bytes of data remain for it");
    needed += el.count * minSize;
  }
}

// === value readers: the same element parsers run over binary and ASCII data

// The element/property being read, for messages.
struct Where {
  const PlyElement* element = nullptr;
  long long index = 0;
  const PlyProperty* property = nullptr;

  std::string describe() const {
    std::string s = element->name + " " + std::to_string(index);
    if (property != nullptr) s += ": property '" + property->name + "'";
    return s;
  }
};

class BinaryValues {
 public:
  BinaryValues(const std::string& bytes, std::size_t offset, bool bigEndian, const std::string& source)
      : p_(reinterpret_cast<const unsigned char*>(bytes.data()) + offset),
        end_(reinterpret_cast<const unsigned char*>(bytes.data()) + bytes.size()),
        swap_(bigEndian != hostIsBigEndian()),
        source_(source) {}

  Where at;

  // A value of an integer-typed property.
  long long integer(PlyType t) {
    switch (t) {
      case PlyType::Int8:
        return get<std::int8_t>();
      case PlyType::UInt8:
        return get<std::uint8_t>();
      case PlyType::Int16:
        return get<std::int16_t>();
      case PlyType::UInt16:
        return get<std::uint16_t>();
      case PlyType::Int32:
        return get<std::int32_t>();
      case PlyType::UInt32:
        return get<std::uint32_t>();
      default:
        break;
    }
    fail(std::string("expected an integer type, found ") + typeName(t));
  }
  double real(PlyType t) {
    if (t == PlyType::Float64) return get<double>();
    if (t == PlyType::Float32) return get<float>();
    return static_cast<double>(integer(t));
  }
  void skip(PlyType t) { need(typeSize(t)), p_ += typeSize(t); }
  void skipBytes(long long n) { need(n), p_ += n; }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_ + ": " + at.describe() + ": " + what);
  }

 private:
  static bool hostIsBigEndian() {
    const std::uint16_t probe = 1;
    unsigned char first = 0;
    std::memcpy(&first, &probe, 1);
    return first == 0;
  }
  void need(long long n) {
    if (end_ - p_ < n)
      fail("expected " + std::to_string(n) + " more bytes, found end of data (" + std::to_string(end_ - p_) +
           " bytes left)");
  }
  template <class T>
  T get() {
    need(static_cast<long long>(sizeof(T)));
    unsigned char buf[sizeof(T)];
    std::memcpy(buf, p_, sizeof(T));
    p_ += sizeof(T);
    if (swap_) std::reverse(buf, buf + sizeof(T));
    T v;
    std::memcpy(&v, buf, sizeof(T));
    return v;
  }

  const unsigned char* p_;
  const unsigned char* end_;
  bool swap_;
  const std::string& source_;
};

class AsciiValues {
 public:
  AsciiValues(const std::string& bytes, std::size_t offset, int firstLine, const std::string& source)
      : sc_(std::string_view(bytes).substr(offset), source, firstLine) {}

  Where at;

  long long integer(PlyType t) {
    const std::string_view tok = sc_.token();
    long long v = 0;
    if (!detail::parseInteger(tok, v))
      fail(std::string("expected an integer (") + typeName(t) + "), found " + found(tok));
    long long lo = 0, hi = 0;
    integerRange(t, lo, hi);
    if (v < lo || v > hi)
      fail("value " + std::to_string(v) + " is out of range for type " + typeName(t) + " [" + std::to_string(lo) +
           ", " + std::to_string(hi) + "]");
    return v;
  }
  double real(PlyType t) {
    if (isIntegerType(t)) return static_cast<double>(integer(t));
    const std::string_view tok = sc_.token();
    double v = 0;
    if (!detail::parseReal(tok, v)) fail(std::string("expected a number (") + typeName(t) + "), found " + found(tok));
    return v;
  }
  void skip(PlyType t) { real(t); }

  [[noreturn]] void fail(const std::string& what) const { sc_.fail(at.describe() + ": " + what); }

 private:
  static std::string found(std::string_view tok) { return tok.empty() ? "end of file" : quoteToken(tok); }
  detail::TextScanner sc_;
};

// === element parsers

// Index range checks name the element and what the index points into.
template <class Values>
int readIndex(Values& in, PlyType t, long long limit, const char* into) {
  const long long v = in.integer(t);
  if (v < 0 || v >= limit)
    in.fail(std::string(into) + " index " + std::to_string(v) + " is out of range [0, " + std::to_string(limit) + ")" +
            (limit == 0 ? std::string(" (no ") + (into[0] == 'v' ? "vertex" : "edge") + " element)" : ""));
  return static_cast<int>(v);
}

template <class Values>
long long readListCount(Values& in, const PlyProperty& p) {
  const long long n = in.integer(p.countType);
  if (n < 0) in.fail("negative list length " + std::to_string(n));
  return n;
}

template <class Values>
void skipProperty(Values& in, const PlyProperty& p) {
  if (!p.isList) {
    in.skip(p.type);
    return;
  }
  const long long n = readListCount(in, p);
  if constexpr (std::is_same_v<Values, BinaryValues>) {
    in.skipBytes(n * typeSize(p.type));  // n < 2^32, size <= 8: no overflow
  } else {
    for (long long k = 0; k < n; ++k) in.skip(p.type);
  }
}

template <class Values>
void skipElement(Values& in, const PlyElement& el) {
  if (el.properties.empty()) return;
  in.at = {&el, 0, nullptr};
  if constexpr (std::is_same_v<Values, BinaryValues>) {
    const bool fixed = std::none_of(el.properties.begin(), el.properties.end(), [](auto& p) { return p.isList; });
    if (fixed) {
      long long size = 0;
      for (const PlyProperty& p : el.properties) size += typeSize(p.type);
      in.skipBytes(el.count * size);  // checkCountsAgainstSize bounded count * size by the file size
      return;
    }
  }
  for (long long i = 0; i < el.count; ++i) {
    in.at.index = i;
    for (const PlyProperty& p : el.properties) {
      in.at.property = &p;
      skipProperty(in, p);
    }
  }
}

template <class Values>
void readVertices(Values& in, const PlyElement& el, MeshData& data) {
  // Role of each property: 0..2 a coordinate, 3 a kept scalar, 4 skipped (a list).
  const std::size_t n = static_cast<std::size_t>(el.count);
  std::vector<int> role(el.properties.size());
  std::vector<std::vector<double>*> column(el.properties.size(), nullptr);
  const bool hasPositions = el.find("x") >= 0;
  for (std::size_t i = 0; i < el.properties.size(); ++i) {
    const PlyProperty& p = el.properties[i];
    const int axis = p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
    if (axis >= 0 && p.isList)
      throw InputError(data.source + ":" + std::to_string(el.line) + ": vertex property '" + p.name +
                       "' is a list; expected a scalar coordinate");
    if (axis >= 0) {
      role[i] = axis;
    } else if (p.isList) {
      role[i] = 4;
    } else {
      role[i] = 3;
      column[i] = &data.vertexProperties[p.name];
      column[i]->resize(n);
    }
  }
  if (hasPositions != (el.find("y") >= 0) || hasPositions != (el.find("z") >= 0))
    throw InputError(data.source + ":" + std::to_string(el.line) +
                     ": element vertex has some but not all of the properties x, y, z; expected all three or none");
  if (hasPositions) data.positions.resize(n);
  in.at = {&el, 0, nullptr};
  for (std::size_t v = 0; v < n; ++v) {
    in.at.index = static_cast<long long>(v);
    for (std::size_t i = 0; i < el.properties.size(); ++i) {
      const PlyProperty& p = el.properties[i];
      in.at.property = &p;
      if (role[i] == 4) {
        skipProperty(in, p);
        continue;
      }
      const double x = in.real(p.type);
      if (!std::isfinite(x)) in.fail("value is " + formatNumber(x) + "; expected a finite number");
      if (role[i] < 3) {
        data.positions[v][role[i]] = x;
      } else {
        (*column[i])[v] = x;
      }
    }
  }
}

template <class Values>
void readFaces(Values& in, const PlyElement& el, MeshData& data, long long nVertices, long long nEdges,
               const std::string& source, const ReadOptions& options) {
  int indices = el.find("vertex_indices");
  if (indices < 0) indices = el.find("vertex_index");
  const int edgeIds = el.find("edge_index");
  const auto headerFail = [&](const std::string& what) {
    throw InputError(source + ":" + std::to_string(el.line) + ": element face: " + what);
  };
  if (indices < 0) headerFail("no list property 'vertex_indices' (or 'vertex_index')");
  if (!el.properties[indices].isList) headerFail("property '" + el.properties[indices].name + "' is not a list");
  if (!isIntegerType(el.properties[indices].type)) headerFail("vertex indices must have an integer type");
  if (edgeIds >= 0) {
    if (!el.properties[edgeIds].isList) headerFail("property 'edge_index' is not a list");
    if (!isIntegerType(el.properties[edgeIds].type)) headerFail("edge_index must have an integer type");
    if (nEdges < 0) headerFail("has 'edge_index' but the file has no element edge with vertex1, vertex2, length");
  }
  const bool deltaComplex = edgeIds >= 0;  // self-loops are legal there, so corners may repeat a vertex
  const std::size_t n = static_cast<std::size_t>(el.count);
  data.faces.reserve(n);
  if (deltaComplex) data.cornerEdges.reserve(n);
  std::vector<int> corners;
  std::array<int, 3> cornerEdge{};
  in.at = {&el, 0, nullptr};
  for (std::size_t f = 0; f < n; ++f) {
    in.at.index = static_cast<long long>(f);
    corners.clear();
    for (std::size_t i = 0; i < el.properties.size(); ++i) {
      const PlyProperty& p = el.properties[i];
      in.at.property = &p;
      if (static_cast<int>(i) == indices) {
        const long long m = readListCount(in, p);
        if (m < 3) in.fail("the list has " + std::to_string(m) + " vertices; expected at least 3");
        for (long long k = 0; k < m; ++k) corners.push_back(readIndex(in, p.type, nVertices, "vertex"));
      } else if (static_cast<int>(i) == edgeIds) {
        const long long nCornerEdges = readListCount(in, p);
        if (nCornerEdges != 3) in.fail("has " + std::to_string(nCornerEdges) + " entries; expected 3 (one per side)");
        for (int k = 0; k < 3; ++k) cornerEdge[k] = readIndex(in, p.type, nEdges, "edge");
      } else {
        skipProperty(in, p);
      }
    }
    in.at.property = nullptr;
    if (deltaComplex) {
      if (corners.size() != 3)
        in.fail("has " + std::to_string(corners.size()) + " vertices; faces with edge_index must be triangles");
      data.cornerEdges.push_back(cornerEdge);
    }
    if (corners.size() > 3) ++data.polygonsTriangulated;
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      const int a = corners[0], b = corners[k], c = corners[k + 1];
      if (!deltaComplex && !options.keepDegenerateFaces && (a == b || b == c || a == c))
        in.fail("repeats vertex " + std::to_string(a == b || a == c ? a : b) +
                "; a triangle needs three distinct vertices (use edge_index for a Δ-complex with self-loops, or "
                "`--repair` to drop such faces)");
      data.faces.push_back({a, b, c});
    }
  }
}

// `element tristrips` (Stanford scans, VCG): one or more records, each a list `vertex_indices` holding triangle
// strips separated by -1. Triangle k of a strip v0 v1 v2 ... is (v_k, v_k+1, v_k+2), with v_k and v_k+1 swapped for
// odd k so that the strip's triangles share one orientation. Triangles that repeat a vertex join strips by convention
// and are skipped (counted in MeshData::stripDegenerateSkipped).
template <class Values>
void readTristrips(Values& in, const PlyElement& el, MeshData& data, long long nVertices, const std::string& source) {
  const int indices = el.find("vertex_indices");
  if (indices < 0 || !el.properties[indices].isList || !isIntegerType(el.properties[indices].type))
    throw InputError(source + ":" + std::to_string(el.line) +
                     ": element tristrips: expected a list property 'vertex_indices' of an integer type");
  std::vector<int> strip;
  const auto flush = [&] {
    for (std::size_t k = 0; k + 2 < strip.size(); ++k) {
      int a = strip[k], b = strip[k + 1];
      const int c = strip[k + 2];
      if (k % 2 == 1) std::swap(a, b);
      if (a == b || b == c || a == c) {
        ++data.stripDegenerateSkipped;
        continue;
      }
      data.faces.push_back({a, b, c});
      ++data.stripTriangles;
    }
    strip.clear();
  };
  in.at = {&el, 0, nullptr};
  for (long long r = 0; r < el.count; ++r) {
    in.at.index = r;
    for (std::size_t i = 0; i < el.properties.size(); ++i) {
      const PlyProperty& p = el.properties[i];
      in.at.property = &p;
      if (static_cast<int>(i) != indices) {
        skipProperty(in, p);
        continue;
      }
      const long long m = readListCount(in, p);
      for (long long k = 0; k < m; ++k) {
        const long long v = in.integer(p.type);
        if (v == -1) {
          flush();
          continue;
        }
        if (v < 0 || v >= nVertices)
          in.fail("vertex index " + std::to_string(v) + " is out of range [0, " + std::to_string(nVertices) +
                  ") (-1 separates strips)");
        strip.push_back(static_cast<int>(v));
      }
      flush();
    }
  }
}

template <class Values>
void readEdges(Values& in, const PlyElement& el, MeshData& data, long long nVertices) {
  const std::size_t n = static_cast<std::size_t>(el.count);
  // Role: 0 vertex1, 1 vertex2, 2 length, 3 kept scalar, 4 skipped list.
  std::vector<int> role(el.properties.size());
  std::vector<std::vector<double>*> column(el.properties.size(), nullptr);
  for (std::size_t i = 0; i < el.properties.size(); ++i) {
    const PlyProperty& p = el.properties[i];
    const int r = p.name == "vertex1" ? 0 : p.name == "vertex2" ? 1 : p.name == "length" ? 2 : -1;
    if (r >= 0 && p.isList)
      throw InputError(data.source + ":" + std::to_string(el.line) + ": edge property '" + p.name +
                       "' is a list; expected a scalar");
    if (r >= 0 && r < 2 && !isIntegerType(p.type))
      throw InputError(data.source + ":" + std::to_string(el.line) + ": edge property '" + p.name + "' has type " +
                       typeName(p.type) + "; expected an integer type");
    if (r >= 0) {
      role[i] = r;
    } else if (p.isList) {
      role[i] = 4;
    } else {
      role[i] = 3;
      column[i] = &data.edgeProperties[p.name];
      column[i]->resize(n);
    }
  }
  data.edges.resize(n);
  in.at = {&el, 0, nullptr};
  for (std::size_t e = 0; e < n; ++e) {
    in.at.index = static_cast<long long>(e);
    EdgeRecord& rec = data.edges[e];
    for (std::size_t i = 0; i < el.properties.size(); ++i) {
      const PlyProperty& p = el.properties[i];
      in.at.property = &p;
      switch (role[i]) {
        case 0:
          rec.v0 = readIndex(in, p.type, nVertices, "vertex");
          break;
        case 1:
          rec.v1 = readIndex(in, p.type, nVertices, "vertex");
          break;
        case 4:
          skipProperty(in, p);
          break;
        default: {
          const double x = in.real(p.type);
          if (!std::isfinite(x)) in.fail("value is " + formatNumber(x) + "; expected a finite number");
          if (role[i] == 2) {
            rec.length = x;
          } else {
            (*column[i])[e] = x;
          }
        }
      }
    }
    // After the whole record, so that the message can name both endpoints whatever the property order.
    if (!(rec.length > 0)) {
      in.at.property = nullptr;
      in.fail("length " + formatNumber(rec.length) + " of the edge joining vertices " + std::to_string(rec.v0) + "–" +
              std::to_string(rec.v1) + " is not positive; expected a finite positive length");
    }
  }
}

bool isLengthEdgeElement(const PlyElement& el) {
  return el.name == "edge" && el.find("vertex1") >= 0 && el.find("vertex2") >= 0 && el.find("length") >= 0;
}

template <class Values>
void readBody(Values& in, const PlyHeader& h, MeshData& data, const ReadOptions& options) {
  long long nVertices = 0;
  long long nEdges = -1;  // -1: no edge element with lengths
  for (const PlyElement& el : h.elements) {
    if (el.name == "vertex") nVertices = el.count;
    if (isLengthEdgeElement(el)) nEdges = el.count;
  }
  // Before reading anything: indices are stored as int, so every element they refer to must be countable by one.
  for (const PlyElement& el : h.elements)
    if ((el.name == "vertex" || el.name == "face" || isLengthEdgeElement(el)) && el.count > INT_MAX)
      throw InputError(data.source + ":" + std::to_string(el.line) + ": element " + el.name + " count " +
                       std::to_string(el.count) + " exceeds the supported maximum 2^31-1");
  bool haveFaces = false;
  for (const PlyElement& el : h.elements) {
    if (el.name == "vertex") {
      readVertices(in, el, data);
    } else if (el.name == "face") {
      readFaces(in, el, data, nVertices, nEdges, data.source, options);
      haveFaces = true;
    } else if (el.name == "tristrips") {
      readTristrips(in, el, data, nVertices, data.source);
      haveFaces = true;
    } else if (isLengthEdgeElement(el)) {
      readEdges(in, el, data, nVertices);
    } else {
      skipElement(in, el);
    }
  }
  if (!haveFaces)
    throw InputError(data.source + ": no 'element face' or 'element tristrips' in the header; expected a triangle mesh");
  if (data.faces.empty())
    throw InputError(data.source + ": element face" + (data.stripDegenerateSkipped > 0 ? " (or tristrips)" : "") +
                     " is empty; expected a triangle mesh");
  data.nVertices = static_cast<int>(nVertices);
}

// A vertex element without properties costs no bytes, so the size check cannot bound its count; a count beyond every
// corner and edge end the file holds is implausible and would only make later stages allocate for nothing.
void checkPropertylessVertexCount(const PlyHeader& h, const MeshData& data) {
  for (const PlyElement& el : h.elements)
    if (el.name == "vertex" && el.properties.empty()) {
      const long long referenced = 3LL * static_cast<long long>(data.faces.size()) + 2LL * data.edges.size();
      if (el.count > referenced)
        throw InputError(data.source + ":" + std::to_string(el.line) + ": element vertex declares " +
                         std::to_string(el.count) + " vertices without properties, but the faces and edges can " +
                         "reference at most " + std::to_string(referenced));
    }
}

// Each face side k (corners k, k+1) must be glued along an edge with those endpoints.
void checkCornerEdges(const MeshData& data) {
  for (std::size_t f = 0; f < data.cornerEdges.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = data.faces[f][k], b = data.faces[f][(k + 1) % 3];
      const EdgeRecord& e = data.edges[static_cast<std::size_t>(data.cornerEdges[f][k])];
      if (!((e.v0 == a && e.v1 == b) || (e.v0 == b && e.v1 == a)))
        throw InputError(data.source + ": face " + std::to_string(f) + ": edge_index[" + std::to_string(k) +
                         "] = " + std::to_string(data.cornerEdges[f][k]) + " is the edge joining vertices " +
                         std::to_string(e.v0) + "–" + std::to_string(e.v1) + ", but side " + std::to_string(k) +
                         " of the face joins vertices " + std::to_string(a) + "–" + std::to_string(b));
    }
}

// === writer helpers

class PlyBodyWriter {
 public:
  PlyBodyWriter(std::string& out, PlyEncoding enc) : out_(out), enc_(enc) {}
  void real(double x) {
    if (enc_ == PlyEncoding::Ascii) {
      separate();
      detail::appendReal(out_, x);
    } else {
      put(x);
    }
  }
  void integer(std::int32_t x) {
    if (enc_ == PlyEncoding::Ascii) {
      separate();
      detail::appendInt(out_, x);
    } else {
      put(x);
    }
  }
  void count(std::uint8_t n) {
    if (enc_ == PlyEncoding::Ascii) {
      separate();
      detail::appendInt(out_, n);
    } else {
      out_.push_back(static_cast<char>(n));
    }
  }
  void endElement() {
    if (enc_ == PlyEncoding::Ascii) out_ += '\n';
    first_ = true;
  }

 private:
  void separate() {
    if (!first_) out_ += ' ';
    first_ = false;
  }
  template <class T>
  void put(T v) {
    char buf[sizeof(T)];
    std::memcpy(buf, &v, sizeof(T));
    const std::uint16_t probe = 1;
    unsigned char little = 0;
    std::memcpy(&little, &probe, 1);
    if ((enc_ == PlyEncoding::BinaryBigEndian) == (little == 1)) std::reverse(buf, buf + sizeof(T));
    out_.append(buf, sizeof(T));
  }
  std::string& out_;
  PlyEncoding enc_;
  bool first_ = true;
};

}  // namespace

MeshData parsePly(const std::string& bytes, const std::string& source, const ReadOptions& options) {
  MeshData data;
  data.source = source;
  const PlyHeader h = parseHeader(bytes, data);
  checkCountsAgainstSize(h, bytes.size(), source);
  if (h.encoding == PlyEncoding::Ascii) {
    AsciiValues in(bytes, h.dataOffset, h.dataLine, source);
    readBody(in, h, data, options);
  } else {
    BinaryValues in(bytes, h.dataOffset, h.encoding == PlyEncoding::BinaryBigEndian, source);
    readBody(in, h, data, options);
  }
  checkPropertylessVertexCount(h, data);
  checkCornerEdges(data);
  return data;
}

namespace detail {

std::string serializePly(const MeshData& data, PlyEncoding encoding) {
  std::string out;
  const bool hasPositions = !data.positions.empty();
  const bool hasEdges = !data.edges.empty();
  const bool hasCornerEdges = !data.cornerEdges.empty();
  out += "ply\nformat ";
  out += encoding == PlyEncoding::Ascii                ? "ascii"
         : encoding == PlyEncoding::BinaryLittleEndian ? "binary_little_endian"
                                                       : "binary_big_endian";
  out += " 1.0\ncomment geometry " + toString(data.background) + "\n";
  for (const std::string& c : data.comments) out += "comment " + c + "\n";
  out += "element vertex " + std::to_string(data.nVertices) + "\n";
  if (hasPositions) out += "property double x\nproperty double y\nproperty double z\n";
  for (const auto& [name, values] : data.vertexProperties) out += "property double " + name + "\n";
  out += "element face " + std::to_string(data.faces.size()) + "\nproperty list uchar int vertex_indices\n";
  if (hasCornerEdges) out += "property list uchar int edge_index\n";
  if (hasEdges) {
    out += "element edge " + std::to_string(data.edges.size()) +
           "\nproperty int vertex1\nproperty int vertex2\nproperty double length\n";
    for (const auto& [name, values] : data.edgeProperties) out += "property double " + name + "\n";
  }
  out += "end_header\n";

  const std::size_t perVertex = (hasPositions ? 3 : 0) + data.vertexProperties.size();
  out.reserve(out.size() + static_cast<std::size_t>(data.nVertices) * perVertex * 24 + data.faces.size() * 40 +
              data.edges.size() * (40 + 24 * data.edgeProperties.size()));
  PlyBodyWriter w(out, encoding);
  for (int v = 0; v < data.nVertices; ++v) {
    if (hasPositions)
      for (int k = 0; k < 3; ++k) w.real(data.positions[v][k]);
    for (const auto& [name, values] : data.vertexProperties) w.real(values[v]);
    w.endElement();
  }
  for (std::size_t f = 0; f < data.faces.size(); ++f) {
    w.count(3);
    for (int k = 0; k < 3; ++k) w.integer(data.faces[f][k]);
    if (hasCornerEdges) {
      w.count(3);
      for (int k = 0; k < 3; ++k) w.integer(data.cornerEdges[f][k]);
    }
    w.endElement();
  }
  for (std::size_t e = 0; e < data.edges.size(); ++e) {
    w.integer(data.edges[e].v0);
    w.integer(data.edges[e].v1);
    w.real(data.edges[e].length);
    for (const auto& [name, values] : data.edgeProperties) w.real(values[e]);
    w.endElement();
  }
  return out;
}

}  // namespace detail

}  // namespace conformesh::intrinsic
