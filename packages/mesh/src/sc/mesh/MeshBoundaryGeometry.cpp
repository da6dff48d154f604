#include <sc/mesh/MeshBoundaryGeometry.hpp>

#include <sc/core/Error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>

namespace sc::mesh {

namespace {

using Point = std::array<double, 3>;

Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point cross(const Point& a, const Point& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Point& a) { return std::sqrt(dot(a, a)); }

// The angle (radians) between u and w.
double angle(const Point& u, const Point& w)
{
  const double c = dot(u, w) / (norm(u) * norm(w));
  return std::acos(std::clamp(c, -1.0, 1.0));
}

// Quadratic Lagrange shape functions and derivatives.
// 2D, t in [0, 1]: nodes v0 (t = 0), v1 (t = 1), m (t = 1/2).
void line3(double t, double N[3], double dN[3], double d2N[3])
{
  N[0] = (1 - t) * (1 - 2 * t), N[1] = t * (2 * t - 1), N[2] = 4 * t * (1 - t);
  dN[0] = 4 * t - 3, dN[1] = 4 * t - 1, dN[2] = 4 - 8 * t;
  d2N[0] = 4, d2N[1] = 4, d2N[2] = -8;
}
// 3D, (r, s) in the reference triangle: v0 (0, 0), v1 (1, 0), v2 (0, 1), m01, m12, m20.
void tri6(double r, double s, double N[6], double Nr[6], double Ns[6])
{
  const double l0 = 1 - r - s, l1 = r, l2 = s;
  N[0] = l0 * (2 * l0 - 1), N[1] = l1 * (2 * l1 - 1), N[2] = l2 * (2 * l2 - 1);
  N[3] = 4 * l0 * l1, N[4] = 4 * l1 * l2, N[5] = 4 * l2 * l0;
  Nr[0] = -(4 * l0 - 1), Nr[1] = 4 * l1 - 1, Nr[2] = 0;
  Nr[3] = 4 * (l0 - l1), Nr[4] = 4 * l2, Nr[5] = -4 * l2;
  Ns[0] = -(4 * l0 - 1), Ns[1] = 0, Ns[2] = 4 * l2 - 1;
  Ns[3] = -4 * l1, Ns[4] = 4 * l1, Ns[5] = 4 * (l0 - l2);
}
// Second derivatives of tri6 (constant): N_rr, N_rs, N_ss.
constexpr double kNrr[6] = {4, 4, 0, -8, 0, 0};
constexpr double kNrs[6] = {4, 0, 0, -4, 4, -4};
constexpr double kNss[6] = {4, 0, 4, 0, 0, -8};

// Closest point of the reference triangle to (r, s) (Euclidean in the reference plane).
void clampToTriangle(double& r, double& s)
{
  if (r >= 0 && s >= 0 && r + s <= 1) return;
  auto best = std::numeric_limits<double>::max();
  double br = 0, bs = 0;
  auto tryPoint = [&](double pr, double ps) {
    const double d = (pr - r) * (pr - r) + (ps - s) * (ps - s);
    if (d < best) best = d, br = pr, bs = ps;
  };
  tryPoint(std::clamp(r, 0.0, 1.0), 0.0);
  tryPoint(0.0, std::clamp(s, 0.0, 1.0));
  const double t = std::clamp(0.5 * (r - s + 1), 0.0, 1.0);  // the edge r + s = 1
  tryPoint(t, 1 - t);
  r = br, s = bs;
}

}  // namespace

struct MeshBoundaryGeometry::Bins {
  double lo[3] = {0, 0, 0};
  double size = 1;
  std::vector<int> faces;  // all faces of the part
  std::unordered_map<long long, std::vector<int>> cells;
  long long key(long long i, long long j, long long k) const
  {
    return (i + (1LL << 20)) + ((j + (1LL << 20)) << 21) + ((k + (1LL << 20)) << 42);
  }
  long long cell(double x, int axis) const
  {
    // Clamped so that a point far from the part (never one that refinement makes) cannot
    // overflow the key; such a point finds no cell and falls back to all faces.
    const double c = std::floor((x - lo[axis]) / size);
    return static_cast<long long>(std::clamp(c, -1e5, 1e5));
  }
};

MeshBoundaryGeometry::MeshBoundaryGeometry(int dim, std::vector<std::string> names,
                                           std::vector<double> faceNodes, std::vector<int> facePart,
                                           std::string origin,
                                           const std::vector<std::size_t>* faceLabels)
    : dim_(dim), names_(std::move(names)), nodes_(std::move(faceNodes)), part_(std::move(facePart)),
      origin_(std::move(origin))
{
  const int nn = nodesPerFace(dim_);
  const int nf = static_cast<int>(part_.size());
  SC_THROW_IF(nodes_.size() != static_cast<std::size_t>(nf) * nn * 3, core::InternalError,
              "MeshBoundaryGeometry: " << nodes_.size() << " coordinates for " << nf << " faces");
  partCurved_.assign(names_.size(), 0);
  auto node = [&](int f, int i) {
    const double* p = &nodes_[(static_cast<std::size_t>(f) * nn + i) * 3];
    return Point{p[0], p[1], p[2]};
  };
  auto faceName = [&](int f) {
    std::ostringstream os;
    os << "the boundary face of physical group '" << names_[part_[f]] << "'";
    if (faceLabels) {
      os << " with nodes";
      for (int i = 0; i < nn; ++i)
        os << (i ? ", " : " ") << (*faceLabels)[static_cast<std::size_t>(f) * nn + i];
    }
    return os.str();
  };
  constexpr int kEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  const int nEdges = dim_ == 2 ? 1 : 3;
  std::vector<double> inflate(nf, 0.0);
  for (int f = 0; f < nf; ++f) {
    double size = 0.0;
    for (int e = 0; e < nEdges; ++e) {
      const Point a = node(f, kEdges[e][0]), b = node(f, kEdges[e][1]);
      const Point m = node(f, dim_ == 2 ? 2 : 3 + e);
      const Point chord = sub(b, a);
      const double length = norm(chord);
      size = std::max(size, length);
      const Point offset =
          sub(m, Point{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])});
      const double bulge = norm(offset);
      inflate[f] += bulge;
      if (bulge > 1e-10 * length) {
        quadratic_ = true;
        // 2D: a bent face. 3D: only a patch that leaves its plane makes the part curved; a flat
        // part whose edges bend within its plane (a disc bounded by a circle) is not, so that the
        // edges it shares with a curved part are projected onto that part (the flat patches
        // would leave a point on a chord where it is).
        if (dim_ == 2) partCurved_[part_[f]] = 1;
      }
      // The map t -> X(t) along the edge is invertible iff its derivative keeps the chord's
      // direction at both ends: the midpoint node's position along the chord in (1/4, 3/4).
      const double along = dot(sub(m, a), chord) / (length * length);
      SC_THROW_IF(!(length > 0) || !(along > 0.25 && along < 0.75), core::InputError,
                  origin_ << ": " << faceName(f) << " folds: its mid-edge node lies at " << along
                          << " of its chord, outside (0.25, 0.75), so the quadratic "
                          << "map of the face is not invertible. Remesh the part (finer, or "
                          << "with Gmsh's high-order optimisation).");
    }
    if (dim_ == 3) {
      const Point n0 = cross(sub(node(f, 1), node(f, 0)), sub(node(f, 2), node(f, 0)));
      for (int i = 3; i < 6; ++i)
        if (std::abs(dot(sub(node(f, i), node(f, 0)), n0)) > 1e-10 * norm(n0) * size)
          partCurved_[part_[f]] = 1;
      // The patch normal at the vertices and midpoints must keep the flat triangle's side.
      const double pts[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
      for (const auto& q : pts) {
        double N[6], Nr[6], Ns[6];
        tri6(q[0], q[1], N, Nr, Ns);
        Point xr{0, 0, 0}, xs{0, 0, 0};
        for (int i = 0; i < 6; ++i)
          for (int k = 0; k < 3; ++k)
            xr[k] += Nr[i] * node(f, i)[k], xs[k] += Ns[i] * node(f, i)[k];
        SC_THROW_IF(!(dot(cross(xr, xs), n0) > 0), core::InputError,
                    origin_ << ": " << faceName(f) << " folds: its quadratic patch turns over "
                            << "at reference point (" << q[0] << ", " << q[1] << "). Remesh the "
                            << "part (finer, or with Gmsh's high-order optimisation).");
      }
    }
  }

  // A grid of cells per part, cell size the part's largest face: the faces whose (inflated)
  // boxes meet a cell are listed in it.
  bins_.resize(names_.size());
  for (std::size_t p = 0; p < names_.size(); ++p) {
    auto bins = std::make_shared<Bins>();
    double lo[3] = {1e300, 1e300, 1e300}, size = 0.0;
    for (int f = 0; f < nf; ++f) {
      if (part_[f] != static_cast<int>(p)) continue;
      bins->faces.push_back(f);
      double flo[3] = {1e300, 1e300, 1e300}, fhi[3] = {-1e300, -1e300, -1e300};
      for (int i = 0; i < nn; ++i)
        for (int k = 0; k < 3; ++k)
          flo[k] = std::min(flo[k], node(f, i)[k]), fhi[k] = std::max(fhi[k], node(f, i)[k]);
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], flo[k] - inflate[f]);
        size = std::max(size, fhi[k] - flo[k] + 2 * inflate[f]);
      }
    }
    if (bins->faces.empty()) {
      bins_[p] = bins;
      continue;
    }
    std::copy(lo, lo + 3, bins->lo);
    bins->size = size > 0 ? size : 1.0;
    for (int f : bins->faces) {
      long long c0[3], c1[3];
      for (int k = 0; k < 3; ++k) {
        double flo = 1e300, fhi = -1e300;
        for (int i = 0; i < nn; ++i)
          flo = std::min(flo, node(f, i)[k]), fhi = std::max(fhi, node(f, i)[k]);
        c0[k] = bins->cell(flo - inflate[f], k), c1[k] = bins->cell(fhi + inflate[f], k);
      }
      for (long long i = c0[0]; i <= c1[0]; ++i)
        for (long long j = c0[1]; j <= c1[1]; ++j)
          for (long long k = c0[2]; k <= c1[2]; ++k)
            bins->cells[bins->key(i, j, k)].push_back(f);
    }
    bins_[p] = bins;
  }

  // A linear file: its boundary is the polygon of its faces, under refinement too. Say so when a
  // part is visibly not flat.
  if (!quadratic_) {
    double worst = 0.0;
    int worstPart = -1;
    for (std::size_t p = 0; p < names_.size(); ++p) {
      const double a = maxKinkAngleDegrees(static_cast<int>(p));
      if (a > worst) worst = a, worstPart = static_cast<int>(p);
    }
    if (worst > 1.0) {
      std::ostringstream os;
      os.precision(3);
      os << origin_ << " is a linear mesh whose boundary part '" << names_[worstPart]
         << "' is not flat (neighbouring faces meet at angles up to " << worst
         << " degrees): the body is the polygon of the file and stays so under refinement, so "
         << "a curved part converges to its polygon, not to the curved body. Give a second-order "
         << "mesh (6-node triangles / 10-node tetrahedra) or the Gmsh geometry (Mesh/Source = "
         << "'Gmsh geometry') if the part is curved (docs/mesh.md \"Curved boundaries from "
            "files\")";
      warning_ = os.str();
    }
  }
}

int MeshBoundaryGeometry::partIndex(const std::string& name) const
{
  const auto it = std::find(names_.begin(), names_.end(), name);
  return it == names_.end() ? -1 : static_cast<int>(it - names_.begin());
}

bool MeshBoundaryGeometry::isCurved(const std::string& boundaryName) const
{
  const int p = partIndex(boundaryName);
  return p >= 0 && partCurved_[p];
}

double MeshBoundaryGeometry::maxKinkAngleDegrees(int part) const
{
  const int nn = nodesPerFace(dim_);
  auto node = [&](int f, int i) {
    const double* p = &nodes_[(static_cast<std::size_t>(f) * nn + i) * 3];
    return Point{p[0], p[1], p[2]};
  };
  // Shared vertices (2D) or edges (3D), found by their coordinates (copies of the same node).
  std::map<std::vector<double>, std::vector<std::pair<int, int>>> shared;  // -> (face, local)
  const int nf = static_cast<int>(part_.size());
  for (int f = 0; f < nf; ++f) {
    if (part_[f] != part) continue;
    if (dim_ == 2) {
      for (int i = 0; i < 2; ++i) {
        const Point x = node(f, i);
        shared[{x[0], x[1], x[2]}].push_back({f, i});
      }
    } else {
      constexpr int kEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
      for (int e = 0; e < 3; ++e) {
        Point a = node(f, kEdges[e][0]), b = node(f, kEdges[e][1]);
        if (b < a) std::swap(a, b);
        shared[{a[0], a[1], a[2], b[0], b[1], b[2]}].push_back({f, e});
      }
    }
  }
  double worst = 0.0;
  for (const auto& [key, faces] : shared) {
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (std::size_t j = i + 1; j < faces.size(); ++j) {
        const auto [f, a] = faces[i];
        const auto [g, b] = faces[j];
        double kink;
        if (dim_ == 2) {
          // Both segments leave the shared vertex: a straight continuation is a half turn.
          const Point p = node(f, a);
          kink = M_PI - angle(sub(node(f, 1 - a), p), sub(node(g, 1 - b), p));
        } else {
          // Both triangles leave the shared edge: flat is a half turn about it.
          const Point p{key[0], key[1], key[2]}, q{key[3], key[4], key[5]};
          const Point e = sub(q, p);
          auto away = [&](int face, int edge) {
            const Point r = sub(node(face, (edge + 2) % 3), p);
            const double t = dot(r, e) / dot(e, e);
            return Point{r[0] - t * e[0], r[1] - t * e[1], r[2] - t * e[2]};
          };
          kink = M_PI - angle(away(f, a), away(g, b));
        }
        worst = std::max(worst, kink);
      }
  }
  return worst * 180.0 / M_PI;
}

std::array<double, 3> MeshBoundaryGeometry::closestOnFace(int f, const Point& x,
                                                          double& dist2) const
{
  const int nn = nodesPerFace(dim_);
  const double* P = &nodes_[static_cast<std::size_t>(f) * nn * 3];
  if (dim_ == 2) {
    // Newton on (X(t) − x)·X'(t) = 0 from the chord's closest point, then the ends.
    const Point a{P[0], P[1], P[2]}, b{P[3], P[4], P[5]};
    const Point chord = sub(b, a);
    double t = std::clamp(dot(sub(x, a), chord) / dot(chord, chord), 0.0, 1.0);
    auto eval = [&](double s, Point& X, Point& dX, Point& d2X) {
      double N[3], dN[3], d2N[3];
      line3(s, N, dN, d2N);
      X = dX = d2X = Point{0, 0, 0};
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
          X[k] += N[i] * P[3 * i + k], dX[k] += dN[i] * P[3 * i + k],
              d2X[k] += d2N[i] * P[3 * i + k];
    };
    Point X, dX, d2X;
    for (int it = 0; it < 30; ++it) {
      eval(t, X, dX, d2X);
      const Point r = sub(X, x);
      const double g = dot(r, dX), h = dot(dX, dX) + dot(r, d2X);
      const double step = h > 0 ? g / h : g / dot(dX, dX);
      const double next = std::clamp(t - step, 0.0, 1.0);
      const bool done = std::abs(next - t) < 1e-15;
      t = next;
      if (done) break;
    }
    eval(t, X, dX, d2X);
    dist2 = dot(sub(X, x), sub(X, x));
    return X;
  }
  // 3D: projected Newton on the patch's (r, s) from the flat triangle's closest point.
  const Point v0{P[0], P[1], P[2]}, e1 = sub(Point{P[3], P[4], P[5]}, v0),
                                    e2 = sub(Point{P[6], P[7], P[8]}, v0);
  const double a11 = dot(e1, e1), a12 = dot(e1, e2), a22 = dot(e2, e2);
  const double b1 = dot(sub(x, v0), e1), b2 = dot(sub(x, v0), e2), det = a11 * a22 - a12 * a12;
  double r = (a22 * b1 - a12 * b2) / det, s = (a11 * b2 - a12 * b1) / det;
  clampToTriangle(r, s);
  Point X{0, 0, 0};
  for (int it = 0; it < 30; ++it) {
    double N[6], Nr[6], Ns[6];
    tri6(r, s, N, Nr, Ns);
    Point Xr{0, 0, 0}, Xs{0, 0, 0}, Xrr{0, 0, 0}, Xrs{0, 0, 0}, Xss{0, 0, 0};
    X = Point{0, 0, 0};
    for (int i = 0; i < 6; ++i)
      for (int k = 0; k < 3; ++k) {
        const double c = P[3 * i + k];
        X[k] += N[i] * c, Xr[k] += Nr[i] * c, Xs[k] += Ns[i] * c;
        Xrr[k] += kNrr[i] * c, Xrs[k] += kNrs[i] * c, Xss[k] += kNss[i] * c;
      }
    const Point d = sub(X, x);
    const double g1 = dot(d, Xr), g2 = dot(d, Xs);
    double h11 = dot(Xr, Xr) + dot(d, Xrr), h12 = dot(Xr, Xs) + dot(d, Xrs),
           h22 = dot(Xs, Xs) + dot(d, Xss);
    double hdet = h11 * h22 - h12 * h12;
    if (!(h11 > 0 && hdet > 0)) {  // not convex here: Gauss–Newton
      h11 = dot(Xr, Xr), h12 = dot(Xr, Xs), h22 = dot(Xs, Xs);
      hdet = h11 * h22 - h12 * h12;
    }
    double nr = r - (h22 * g1 - h12 * g2) / hdet, ns = s - (h11 * g2 - h12 * g1) / hdet;
    clampToTriangle(nr, ns);
    const bool done = std::abs(nr - r) + std::abs(ns - s) < 1e-15;
    r = nr, s = ns;
    if (done) break;
  }
  double N[6], Nr[6], Ns[6];
  tri6(r, s, N, Nr, Ns);
  X = Point{0, 0, 0};
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 3; ++k)
      X[k] += N[i] * P[3 * i + k];
  dist2 = dot(sub(X, x), sub(X, x));
  return X;
}

std::array<double, 3> MeshBoundaryGeometry::project(const std::string& boundaryName,
                                                    const std::array<double, 3>& x) const
{
  const int p = partIndex(boundaryName);
  if (p < 0 || !partCurved_[p]) return x;
  const Bins& bins = *bins_[p];
  double best = std::numeric_limits<double>::max();
  Point closest = x;
  auto consider = [&](int f) {
    double d2;
    const Point c = closestOnFace(f, x, d2);
    if (d2 < best) best = d2, closest = c;
  };
  // The cells around x first: a face outside them is farther than one cell from x.
  long long c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = bins.cell(x[k], k);
  std::vector<int> seen;
  for (long long i = c[0] - 1; i <= c[0] + 1; ++i)
    for (long long j = c[1] - 1; j <= c[1] + 1; ++j)
      for (long long k = c[2] - 1; k <= c[2] + 1; ++k) {
        const auto it = bins.cells.find(bins.key(i, j, k));
        if (it == bins.cells.end()) continue;
        for (int f : it->second)
          if (std::find(seen.begin(), seen.end(), f) == seen.end()) seen.push_back(f), consider(f);
      }
  if (!(best <= bins.size * bins.size))
    for (int f : bins.faces)
      consider(f);
  return closest;
}

void MeshBoundaryGeometry::addToGmshModel() const
{
  SC_THROW_IF(true, core::InternalError,
              origin_ << ": a mesh file's boundary cannot be meshed again by Gmsh");
}

std::string MeshBoundaryGeometry::classifyBoundaryEntity(const std::array<double, 3>&) const
{
  SC_THROW_IF(true, core::InternalError,
              origin_ << ": a mesh file's boundary has no Gmsh entities to classify");
}

}  // namespace sc::mesh
