// sampled_field.cpp — the sampled field's grid conventions and its text format: parsing, formatting, sampling an
// analytic metric (see sampled_field.h). No HDF5 here: sampled_field_hdf5.cpp reads and writes the other container.
#include "conformesh/intrinsic/metric/sampled_field.h"

#include <cmath>
#include <sstream>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

namespace {

std::string at(const std::string& source, int line) {
  return source + ":" + std::to_string(line);
}

bool parseYesNo(const std::string& word, const std::string& where) {
  if (word == "yes") return true;
  if (word == "no") return false;
  throw InputError(where + ": expected 'yes' or 'no', found '" + word + "'");
}

double parseNumber(const std::string& word, const std::string& where, const std::string& what) {
  try {
    size_t used = 0;
    const double x = std::stod(word, &used);
    if (used != word.size()) throw std::invalid_argument("trailing characters");
    return x;
  } catch (const std::exception&) {
    // stod also rejects "nan"/"inf" spelled oddly; those it accepts are caught by the finiteness checks.
    throw InputError(where + ": " + what + " must be a number, found '" + word + "'");
  }
}

int parseCount(const std::string& word, const std::string& where, const std::string& what) {
  const double x = parseNumber(word, where, what);
  if (!(x >= 1 && x <= 1e6 && x == std::floor(x)))
    throw InputError(where + ": " + what + " must be a positive integer (at most 1e6), found '" + word + "'");
  return static_cast<int>(x);
}

}  // namespace

// =====================================================================================================================
// grid conventions

double SampledField::nodeU(int i) const {
  const ChartDomain& d = domain;
  return d.u0 + i * (d.u1 - d.u0) / (d.periodicU ? nu : nu - 1);
}
double SampledField::nodeV(int j) const {
  const ChartDomain& d = domain;
  if (d.poleAtV0) return (j + 0.5) * M_PI / nv;
  return d.v0 + j * (d.v1 - d.v0) / (d.periodicV ? nv : nv - 1);
}

// =====================================================================================================================
// text format

SampledField parseSampledField(const std::string& text, const std::string& source) {
  SampledField f;
  f.source = source;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0, fieldsLine = 0;
  bool magic = false, haveChart = false, haveGrid = false, inData = false;
  bool havePU = false, havePV = false;
  std::string poles = "none";
  std::vector<int> column(3, -1);  // column of g_uu, g_uv, g_vv in data lines
  int nColumns = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream ls(line);
    std::vector<std::string> w;
    for (std::string t; ls >> t;) w.push_back(t);
    if (w.empty()) continue;
    const std::string where = at(source, lineNo);
    if (!magic) {
      if (w.size() != 2 || w[0] != "conformesh-metric-field" || w[1] != "1")
        throw InputError(where + ": expected the header 'conformesh-metric-field 1', found '" + line + "'");
      magic = true;
      continue;
    }
    if (inData) {
      if (static_cast<int>(w.size()) != nColumns)
        throw InputError(where + ": data line must have " + std::to_string(nColumns) +
                         " numbers (one per field), found " + std::to_string(w.size()));
      if (static_cast<int>(f.guu.size()) == f.nu * f.nv)
        throw InputError(where + ": more data lines than the grid's " + std::to_string(f.nu) + " x " +
                         std::to_string(f.nv) + " = " + std::to_string(f.nu * f.nv) + " nodes");
      const double guu = parseNumber(w[column[0]], where, "g_uu"), guv = parseNumber(w[column[1]], where, "g_uv"),
                   gvv = parseNumber(w[column[2]], where, "g_vv");
      f.guu.push_back(guu), f.guv.push_back(guv), f.gvv.push_back(gvv), f.lines.push_back(lineNo);
      continue;
    }
    const std::string& key = w[0];
    auto need = [&](size_t n) {
      if (w.size() != n + 1)
        throw InputError(where + ": '" + key + "' takes " + std::to_string(n) + " value(s), found " +
                         std::to_string(w.size() - 1));
    };
    if (key == "chart") {
      need(4);
      f.domain.u0 = parseNumber(w[1], where, "U0"), f.domain.u1 = parseNumber(w[2], where, "U1");
      f.domain.v0 = parseNumber(w[3], where, "V0"), f.domain.v1 = parseNumber(w[4], where, "V1");
      checkChartBounds(f.domain, where);
      haveChart = true;
    } else if (key == "grid") {
      need(2);
      f.nu = parseCount(w[1], where, "NU"), f.nv = parseCount(w[2], where, "NV");
      haveGrid = true;
    } else if (key == "periodic_u") {
      need(1);
      f.domain.periodicU = parseYesNo(w[1], where), havePU = true;
    } else if (key == "periodic_v") {
      need(1);
      f.domain.periodicV = parseYesNo(w[1], where), havePV = true;
    } else if (key == "poles") {
      need(1);
      if (w[1] != "none" && w[1] != "both")
        throw InputError(where + ": poles must be 'none' or 'both', found '" + w[1] + "'");
      poles = w[1];
    } else if (key == "fields") {
      fieldsLine = lineNo;
      nColumns = static_cast<int>(w.size()) - 1;
      const char* names[3] = {"g_uu", "g_uv", "g_vv"};
      for (int c = 1; c < static_cast<int>(w.size()); ++c) {
        int k = -1;
        for (int n = 0; n < 3; ++n)
          if (w[c] == names[n]) k = n;
        if (k < 0) throw InputError(where + ": unknown field '" + w[c] + "' (expected g_uu, g_uv, g_vv)");
        if (column[k] >= 0) throw InputError(where + ": field '" + w[c] + "' listed twice");
        column[k] = c - 1;
      }
      for (int n = 0; n < 3; ++n)
        if (column[n] < 0) throw InputError(where + ": missing field '" + std::string(names[n]) + "' in 'fields'");
    } else if (key == "data") {
      need(0);
      const std::string missing = !haveChart        ? "chart"
                                  : !haveGrid       ? "grid"
                                  : !havePU         ? "periodic_u"
                                  : !havePV         ? "periodic_v"
                                  : fieldsLine == 0 ? "fields"
                                                    : "";
      if (!missing.empty()) throw InputError(where + ": 'data' before the '" + missing + "' line");
      inData = true;
    } else {
      throw InputError(where + ": unknown key '" + key +
                       "' (expected chart, grid, periodic_u, periodic_v, poles, fields, data)");
    }
  }
  if (!magic) throw InputError(source + ": empty file (expected the header 'conformesh-metric-field 1')");
  if (!inData) throw InputError(at(source, lineNo) + ": no 'data' line");
  if (static_cast<int>(f.guu.size()) != f.nu * f.nv)
    throw InputError(at(source, lineNo) + ": wrong grid shape: 'grid " + std::to_string(f.nu) + " " +
                     std::to_string(f.nv) + "' needs " + std::to_string(f.nu * f.nv) + " data lines, found " +
                     std::to_string(f.guu.size()));
  if (poles == "both") markPoleToPole(f, source);
  return f;
}

void checkChartBounds(const ChartDomain& d, const std::string& where) {
  if (!(d.u1 > d.u0) || !(d.v1 > d.v0) || !std::isfinite(d.u1 - d.u0) || !std::isfinite(d.v1 - d.v0))
    throw InputError(where + ": chart must have finite U0 < U1 and V0 < V1");
}

void markPoleToPole(SampledField& f, const std::string& where) {
  ChartDomain& d = f.domain;
  if (!d.periodicU || d.periodicV || d.u0 != 0 || std::abs(d.u1 - 2 * M_PI) > 1e-12 || d.v0 != 0 ||
      std::abs(d.v1 - M_PI) > 1e-12)
    throw InputError(where + ": 'poles both' needs periodic_u yes, periodic_v no and chart 0 2pi 0 pi (to 1e-12)");
  d.poleAtV0 = d.poleAtV1 = true;
  d.u1 = 2 * M_PI, d.v1 = M_PI;
}

std::string formatSampledField(const SampledField& f) {
  std::ostringstream s;
  s.precision(17);
  s << "conformesh-metric-field 1\n# " << f.source << "\n";
  s << "chart " << f.domain.u0 << ' ' << f.domain.u1 << ' ' << f.domain.v0 << ' ' << f.domain.v1 << '\n';
  s << "grid " << f.nu << ' ' << f.nv << '\n';
  s << "periodic_u " << (f.domain.periodicU ? "yes" : "no") << "\nperiodic_v " << (f.domain.periodicV ? "yes" : "no")
    << "\npoles " << (f.domain.poleAtV0 ? "both" : "none") << "\nfields g_uu g_uv g_vv\ndata\n";
  for (size_t k = 0; k < f.guu.size(); ++k) s << f.guu[k] << ' ' << f.guv[k] << ' ' << f.gvv[k] << '\n';
  return s.str();
}

SampledField sampleMetric(const SmoothMetric& m, int nu, int nv) {
  SampledField f;
  f.source = "sampled " + m.description();
  f.domain = m.domain();
  const ChartShape shape = f.domain.shape();
  if (shape == ChartShape::Disk)
    throw InputError(m.description() + ": sampled fields support pole-to-pole (sphere) charts, not disk charts");
  f.nu = nu, f.nv = nv;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const Eigen::Matrix2d g = m.g(f.nodeU(i), f.nodeV(j));
      f.guu.push_back(g(0, 0)), f.guv.push_back(g(0, 1)), f.gvv.push_back(g(1, 1));
    }
  return f;
}

}  // namespace conformesh::intrinsic
