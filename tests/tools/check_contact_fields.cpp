// check_contact_fields: the `contact` grid of a cycle's fields (<base>_c<NNNN>.h5 and the .xdmf)
// against the contact CSV of that cycle (docs/output.md "Fields in a run's files",
// "contact_cycle<N>.csv").
//
//   check_contact_fields DIR CYCLE DEGREE points|bernstein [--base NAME] [--perturb]
//
// Both list the contact points in the same order (rank 0's first, each rank's by face). Checked,
// each to 1e-12 relative to the largest magnitude of the CSV column it is compared with:
//   positions        the grid's vertices are the CSV's x, y[, z] (z = 0 in 2D)
//   status           0/1/2 for free/stick/slip
//   contact_pressure −σ_N at the point: the CSV's sigma_n itself (points), or the Bernstein
//                    polynomial of degree DEGREE of the point's face, whose coefficients are the
//                    CSV's sigma_n of the face's rows, at the point's control position α/k
//                    (bernstein; the rows of a face are consecutive, and their positions are
//                    checked to be the face's control points)
//   tangential_traction  2D: σ_T likewise; 3D: a vector whose length is |(σ_T1, σ_T2)| at the
//                    point and which is normal to contact_normal
//   gap, slip        gap × weight = weighted_gap, slip × weight = weighted_slip (3D: |slip|)
//   weight > 0, |contact_normal| = 1
// and the .xdmf lists the grid in the cycle's step with every field. --perturb changes the CSV's
// largest sigma_n by 1e-11 (relative) before comparing: the check must then fail.
// Exit status: 0 all checks hold, 1 a check failed, 2 a file could not be read.
#include <hdf5.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "CsvFields.hpp"

#include <sc/disc/Bernstein.hpp>

namespace {

constexpr double kTolerance = 1e-12;

struct Dataset {
  std::vector<hsize_t> dims;
  std::vector<double> values;
};

bool readDataset(hid_t file, const std::string& path, Dataset& d)
{
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) return false;
  const hid_t space = H5Dget_space(set);
  d.dims.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, d.dims.data(), nullptr);
  hsize_t n = 1;
  for (hsize_t x : d.dims)
    n *= x;
  d.values.assign(n, 0.0);
  const bool ok = n == 0 || H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                                    d.values.data()) >= 0;
  H5Sclose(space);
  H5Dclose(set);
  return ok;
}

using sc::testtools::splitCsvLine;

// The Bernstein basis of a face's constraints, the library's own definition (docs/contact.md
// "Constraint points").
using sc::disc::bernstein;
using sc::disc::bernsteinIndices;

struct Check {
  std::string name;
  double worst = 0.0;  // largest |difference| / scale
  void add(double difference, double scale)
  {
    const double r = scale > 0.0 ? std::abs(difference) / scale : std::abs(difference);
    worst = std::max(worst, std::isnan(r) ? INFINITY : r);
  }
  bool report() const
  {
    const bool ok = worst <= kTolerance;
    std::printf("%-28s max relative difference %.3g (tolerance %.0e) %s\n", name.c_str(), worst,
                kTolerance, ok ? "ok" : "FAILED");
    return ok;
  }
};

}  // namespace

int main(int argc, char** argv)
{
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s DIR CYCLE DEGREE points|bernstein [--base NAME] [--perturb]\n",
                 argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  const int cycle = std::atoi(argv[2]);
  const int k = std::atoi(argv[3]);
  const bool bernsteinCoefficients = std::string(argv[4]) == "bernstein";
  std::string base = "solution";
  bool perturb = false;
  for (int i = 5; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--base" && i + 1 < argc)
      base = argv[++i];
    else if (a == "--perturb")
      perturb = true;
  }

  // The CSV.
  const std::string csvPath = dir + "/contact_cycle" + std::to_string(cycle) + ".csv";
  std::ifstream csv(csvPath);
  std::string line;
  if (!csv || !std::getline(csv, line)) {
    std::fprintf(stderr, "cannot read %s\n", csvPath.c_str());
    return 2;
  }
  const auto header = splitCsvLine(line);
  std::map<std::string, std::size_t> col;
  for (std::size_t i = 0; i < header.size(); ++i)
    col[header[i]] = i;
  const int dim = col.count("z") ? 3 : 2;
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line))
    if (!line.empty()) rows.push_back(splitCsvLine(line));
  const std::size_t n = rows.size();
  auto num = [&](std::size_t r, const std::string& c) { return std::stod(rows[r].at(col.at(c))); };
  std::vector<std::array<double, 3>> x(n);
  std::vector<double> sn(n), st1(n), st2(n, 0.0), wgap(n), wslip(n), status(n);
  for (std::size_t r = 0; r < n; ++r) {
    for (int c = 0; c < dim; ++c)
      x[r][c] = num(r, std::string(1, "xyz"[c]));
    sn[r] = num(r, "sigma_n");
    st1[r] = num(r, "sigma_t");
    if (dim == 3) st2[r] = num(r, "sigma_t2");
    wgap[r] = num(r, "weighted_gap");
    wslip[r] = num(r, "weighted_slip");
    const std::string s = rows[r].at(col.at("status"));
    status[r] = s == "free" ? 0 : s == "stick" ? 1 : s == "slip" ? 2 : -1;
  }
  auto maxAbs = [](const std::vector<double>& v) {
    double m = 0.0;
    for (double a : v)
      m = std::max(m, std::abs(a));
    return m;
  };
  if (perturb && n > 0) {
    const auto it = std::max_element(sn.begin(), sn.end(),
                                     [](double a, double b) { return std::abs(a) < std::abs(b); });
    *it *= 1.0 + 1e-11;
    std::printf("perturbed: the largest sigma_n changed by 1e-11 (relative)\n");
  }

  // The fields.
  char h5Name[64];
  std::snprintf(h5Name, sizeof h5Name, "_c%04d.h5", cycle);
  const std::string h5Path = dir + "/" + base + h5Name;
  const hid_t file = H5Fopen(h5Path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) {
    std::fprintf(stderr, "cannot open %s\n", h5Path.c_str());
    return 2;
  }
  const std::vector<std::string> fields{"contact_pressure", "tangential_traction", "gap",   "slip",
                                        "weight",           "contact_normal",      "status"};
  std::map<std::string, Dataset> f;
  bool read = readDataset(file, "/contact/geometry", f["geometry"]);
  for (const auto& name : fields)
    read = readDataset(file, "/contact/point/" + name, f[name]) && read;
  H5Fclose(file);
  if (!read) {
    std::fprintf(stderr, "%s: a dataset of the contact grid is missing\n", h5Path.c_str());
    return 2;
  }
  bool ok = true;
  auto fail = [&](const std::string& why) {
    std::printf("FAILED: %s\n", why.c_str());
    ok = false;
  };
  if (f["geometry"].dims != std::vector<hsize_t>{n, 3})
    fail("the contact grid has " +
         std::to_string(f["geometry"].dims.empty() ? 0 : f["geometry"].dims[0]) +
         " points, the CSV " + std::to_string(n));
  for (const auto& name : fields) {
    const bool vector =
        name == "contact_normal" || (dim == 3 && (name == "tangential_traction" || name == "slip"));
    const std::vector<hsize_t> want = vector ? std::vector<hsize_t>{n, 3} : std::vector<hsize_t>{n};
    if (f[name].dims != want) fail("/contact/point/" + name + " has the wrong shape");
  }
  if (!ok) return 1;

  // Positions and status: exact (%.17g round-trips).
  std::size_t moved = 0, wrongStatus = 0;
  for (std::size_t r = 0; r < n; ++r) {
    for (int c = 0; c < 3; ++c)
      moved += f["geometry"].values[3 * r + c] != (c < dim ? x[r][c] : 0.0);
    wrongStatus += f["status"].values[r] != status[r];
  }
  if (moved) fail(std::to_string(moved) + " coordinates differ from the CSV's");
  if (wrongStatus)
    fail(std::to_string(wrongStatus) + " points have another status than in the CSV");

  // The traction at each point from the CSV's coefficients.
  std::vector<double> pn(n), pt1(n), pt2(n);
  Check faces{"control points of the faces"};
  if (!bernsteinCoefficients) {
    pn = sn, pt1 = st1, pt2 = st2;
  } else {
    const auto alphas = bernsteinIndices(k, dim);
    const std::size_t m = alphas.size();
    if (n % m != 0)
      fail(std::to_string(n) + " rows are not whole faces of " + std::to_string(m) + " points");
    double size = 0.0;
    for (const auto& p : x)
      for (int c = 0; c < dim; ++c)
        size = std::max(size, std::abs(p[c]));
    for (std::size_t f0 = 0; f0 + m <= n; f0 += m) {
      // The face's vertices are its rows with α = k e_i; every row must be its control point.
      std::array<std::array<double, 3>, 3> v{};
      for (std::size_t p = 0; p < m; ++p)
        for (int i = 0; i < dim; ++i)
          if (alphas[p][i] == k) v[i] = x[f0 + p];
      for (std::size_t p = 0; p < m; ++p) {
        std::array<double, 3> lambda{};
        for (int i = 0; i < 3; ++i)
          lambda[i] = alphas[p][i] / static_cast<double>(k);
        for (int c = 0; c < dim; ++c) {
          double xc = 0.0;
          for (int i = 0; i < dim; ++i)
            xc += lambda[i] * v[i][c];
          faces.add(xc - x[f0 + p][c], size);
        }
        double a = 0.0, b = 0.0, c2 = 0.0;
        for (std::size_t q = 0; q < m; ++q) {
          const double w = bernstein(alphas[q], lambda, k);
          a += w * sn[f0 + q];
          b += w * st1[f0 + q];
          c2 += w * st2[f0 + q];
        }
        pn[f0 + p] = a, pt1[f0 + p] = b, pt2[f0 + p] = c2;
      }
    }
  }

  Check pressure{"contact_pressure"}, traction{"tangential_traction"},
      normalToN{"tangential_traction . n"}, gap{"gap x weight"}, slip{"slip x weight"},
      normal{"|contact_normal|"};
  const double scaleN = std::max(maxAbs(sn), 1e-300);
  const double scaleT = std::max(std::max(maxAbs(st1), maxAbs(st2)), scaleN);
  const double scaleGap = maxAbs(wgap), scaleSlip = maxAbs(wslip);
  std::size_t badWeights = 0;
  for (std::size_t r = 0; r < n; ++r) {
    pressure.add(f["contact_pressure"].values[r] - (-pn[r]), scaleN);
    const double w = f["weight"].values[r];
    badWeights += !(w > 0.0);
    const double* nv = &f["contact_normal"].values[3 * r];
    normal.add(std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]) - 1.0, 1.0);
    gap.add(f["gap"].values[r] * w - wgap[r], scaleGap);
    if (dim == 2) {
      traction.add(f["tangential_traction"].values[r] - pt1[r], scaleT);
      slip.add(f["slip"].values[r] * w - wslip[r], scaleSlip);
    } else {
      const double* t = &f["tangential_traction"].values[3 * r];
      const double* s = &f["slip"].values[3 * r];
      traction.add(std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]) - std::hypot(pt1[r], pt2[r]),
                   scaleT);
      normalToN.add(t[0] * nv[0] + t[1] * nv[1] + t[2] * nv[2], scaleT);
      slip.add(std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) * w - wslip[r], scaleSlip);
    }
  }
  if (badWeights) fail(std::to_string(badWeights) + " points have a weight that is not positive");
  std::printf("%zu contact points (%dD, %s, k = %d) in %s\n", n, dim,
              bernsteinCoefficients ? "Bernstein coefficients" : "point values", k, h5Path.c_str());
  std::vector<const Check*> checks{&pressure, &traction, &gap, &slip, &normal};
  if (bernsteinCoefficients) checks.push_back(&faces);
  if (dim == 3) checks.push_back(&normalToN);
  for (const Check* c : checks)
    ok = c->report() && ok;

  // The .xdmf lists the grid in the cycle's step, with every field.
  std::ifstream xin(dir + "/" + base + ".xdmf");
  std::stringstream xs;
  xs << xin.rdbuf();
  const std::string xml = xs.str();
  const std::string stepTag = "<Grid Name=\"cycle " + std::to_string(cycle) + "\"";
  const std::size_t begin = xml.find(stepTag);
  const std::size_t end =
      begin == std::string::npos ? begin : xml.find("<Grid Name=\"cycle ", begin + 1);
  const std::string step =
      begin == std::string::npos ? std::string() : xml.substr(begin, end - begin);
  if (step.find("<Grid Name=\"contact\" GridType=\"Uniform\">") == std::string::npos ||
      step.find("TopologyType=\"Polyvertex\" NumberOfElements=\"" + std::to_string(n) +
                "\" NodesPerElement=\"1\"") == std::string::npos)
    fail(base + ".xdmf does not list the contact grid of " + std::to_string(n) +
         " points in cycle " + std::to_string(cycle));
  for (const auto& name : fields)
    if (step.find("<Attribute Name=\"" + name + "\"") == std::string::npos)
      fail(base + ".xdmf lists no field " + name + " in cycle " + std::to_string(cycle));
  std::printf("%s\n", ok ? "all checks hold" : "some checks FAILED");
  return ok ? 0 : 1;
}
