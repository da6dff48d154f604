#include <sc/mesh/BisectionRefiner.hpp>

#include <sc/core/Error.hpp>

#include <algorithm>
#include <chrono>
#include <numeric>

namespace sc::mesh {

// 3D marking code of a tetrahedron (a, b, c, d) with refinement edge ab (AMP notation):
//   bits 0-1  ma: marked edge of the face acd (opposite b): 0 = ac, 1 = ad, 2 = cd
//   bits 2-3  mb: marked edge of the face bcd (opposite a): 0 = bc, 1 = bd, 2 = cd
//   bit  4    flag (only meaningful for planar tetrahedra)
// The two faces containing ab are marked at ab. Types: planar P (ma = mb = 0, the marked edges
// meet at c — a planar tetrahedron with common vertex d is stored with c and d swapped), adjacent
// A (one of ma, mb is cd), opposite O (both cd), mixed M (ac/bd or ad/bc).
namespace {
constexpr int kMaxPasses = 10000;

inline double dist2(const double* x, const double* y, int d)
{
  double s = 0;
  for (int i = 0; i < d; ++i)
    s += (x[i] - y[i]) * (x[i] - y[i]);
  return s;
}

using Clock = std::chrono::steady_clock;
inline double seconds(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}
}  // namespace

BisectionRefiner::BisectionRefiner(Teuchos::RCP<const SimplexMesh> initialMesh,
                                   Teuchos::RCP<const Geometry> geometry, bool projectBoundary)
    : dim_(initialMesh->dim()), mesh_(initialMesh), geometry_(geometry),
      project_(projectBoundary && !geometry.is_null()), names_(initialMesh->boundaryNames()),
      origin_(initialMesh->origin())
{
  const SimplexMesh& m = *initialMesh;
  SC_THROW_IF(!geometry.is_null() && geometry->dim() != dim_, sc::core::InternalError,
              "BisectionRefiner: geometry of dimension " << geometry->dim()
                                                         << " for a mesh of dimension " << dim_);
  partCurved_.resize(names_.size(), 0);
  for (std::size_t i = 0; i < names_.size(); ++i)
    partCurved_[i] = project_ && geometry_->isCurved(names_[i]);
  coords_ = m.coordinates();
  verts_ = m.elementVertices();
  const int ne = m.numElements();
  gen_.assign(ne, 0);

  // Strict global order of edges (length, then vertex ids) so that neighbours choose the same
  // longest edge of a shared face.
  auto longer = [&](int a, int b, int c, int d) {
    const double l1 = dist2(m.vertex(a), m.vertex(b), dim_),
                 l2 = dist2(m.vertex(c), m.vertex(d), dim_);
    if (l1 != l2) return l1 > l2;
    return edgeKey(a, b) > edgeKey(c, d);
  };

  if (dim_ == 2) {
    for (int e = 0; e < ne; ++e) {
      int* v = &verts_[static_cast<std::size_t>(e) * 3];
      // Rotate (keeps orientation) so that the longest edge is v0v1.
      int best = 0;  // edge (v[i], v[i+1])
      for (int i = 1; i < 3; ++i)
        if (longer(v[i], v[(i + 1) % 3], v[best], v[(best + 1) % 3])) best = i;
      std::rotate(v, v + best, v + 3);
    }
    for (int f : m.boundaryFaces()) {
      const int* fv = m.faceVertices(f);
      boundaryEdges_.insert(edgeKey(fv[0], fv[1]), m.faceBoundaryId(f));
    }
  } else {
    code_.assign(ne, 0);
    for (int e = 0; e < ne; ++e) {
      const int* v = m.elementVertices(e);
      // Refinement edge: longest edge.
      int bi = 0, bj = 1;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          if (longer(v[i], v[j], v[bi], v[bj])) bi = i, bj = j;
      int w[4] = {v[bi], v[bj], 0, 0}, k = 2;
      for (int i = 0; i < 4; ++i)
        if (i != bi && i != bj) w[k++] = v[i];
      // Each face marked at its longest edge.
      auto faceMarker = [&](int x, int y, int z) -> std::array<int, 2> {
        std::array<int, 2> best{x, y};
        if (longer(x, z, best[0], best[1])) best = {x, z};
        if (longer(y, z, best[0], best[1])) best = {y, z};
        return best;
      };
      std::array<int, 2> markers[4] = {
          faceMarker(w[1], w[2], w[3]), faceMarker(w[0], w[2], w[3]), {w[0], w[1]}, {w[0], w[1]}};
      setTetrahedron(e, w, markers, false);
    }
    for (int f : m.boundaryFaces()) {
      const int* fv = m.faceVertices(f);
      const int part = m.faceBoundaryId(f);
      boundaryFaces_.insert(faceKey(fv[0], fv[1], fv[2]), part);
      if (partCurved_[part]) {
        curvedEdges_.insert(edgeKey(fv[0], fv[1]), part);
        curvedEdges_.insert(edgeKey(fv[0], fv[2]), part);
        curvedEdges_.insert(edgeKey(fv[1], fv[2]), part);
      }
    }
  }
}

// Store tetrahedron w (4 vertices) in `slot`: markers[i] is the marked edge of the face opposite
// w[i]; the refinement edge is markers[3] (the face inherited from the parent, or for an initial
// tetrahedron its longest edge listed as markers[2] = markers[3]).
void BisectionRefiner::setTetrahedron(int slot, const int w[4], const std::array<int, 2> markers[4],
                                      bool flag)
{
  auto localOf = [&](int v) {
    for (int i = 0; i < 4; ++i)
      if (w[i] == v) return i;
    return -1;
  };
  const int p = markers[3][0], q = markers[3][1];
  int rs[2], k = 0;
  for (int i = 0; i < 4; ++i)
    if (w[i] != p && w[i] != q) rs[k++] = w[i];
  int r = rs[0], s = rs[1];
  const auto& Ma = markers[localOf(q)];  // face (p, r, s)
  const auto& Mb = markers[localOf(p)];  // face (q, r, s)
  auto codeA = [&](const std::array<int, 2>& e) {
    const bool hasP = e[0] == p || e[1] == p, hasR = e[0] == r || e[1] == r;
    return hasP ? (hasR ? 0 : 1) : 2;
  };
  auto codeB = [&](const std::array<int, 2>& e) {
    const bool hasQ = e[0] == q || e[1] == q, hasR = e[0] == r || e[1] == r;
    return hasQ ? (hasR ? 0 : 1) : 2;
  };
  int ma = codeA(Ma), mb = codeB(Mb);
  if (ma == 1 && mb == 1) {  // planar with common vertex s: store it as c
    std::swap(r, s);
    ma = mb = 0;
  }
  int* v = &verts_[static_cast<std::size_t>(slot) * 4];
  v[0] = p, v[1] = q, v[2] = r, v[3] = s;
  code_[slot] = static_cast<unsigned char>(ma | (mb << 2) | (flag ? 16 : 0));
}

std::array<double, 3> BisectionRefiner::point(int v) const
{
  std::array<double, 3> x{0, 0, 0};
  for (int k = 0; k < dim_; ++k)
    x[k] = coords_[static_cast<std::size_t>(v) * dim_ + k];
  return x;
}

int BisectionRefiner::midpoint(int a, int b)
{
  const std::uint64_t key = edgeKey(a, b);
  const int next = static_cast<int>(coords_.size()) / dim_;
  auto [val, inserted] = midpoints_.insert(key, next);
  if (!inserted) return *val;
  std::array<double, 3> x{0, 0, 0};
  for (int k = 0; k < dim_; ++k)
    x[k] = 0.5 * (coords_[static_cast<std::size_t>(a) * dim_ + k] +
                  coords_[static_cast<std::size_t>(b) * dim_ + k]);
  if (project_) {
    const int* part = dim_ == 2 ? boundaryEdges_.find(key) : curvedEdges_.find(key);
    if (part && *part >= 0 && partCurved_[*part]) x = geometry_->project(names_[*part], x);
  }
  for (int k = 0; k < dim_; ++k)
    coords_.push_back(x[k]);
  step_->newVertexParents.push_back({std::min(a, b), std::max(a, b)});
  splitEndpoint_.push_back(0);
  splitEndpoint_[a] = splitEndpoint_[b] = 1;
  return next;
}

bool BisectionRefiner::needsBisection(int e) const
{
  if (gen_[e] < target_[e]) return true;
  const int nve = dim_ + 1;
  const int* v = &verts_[static_cast<std::size_t>(e) * nve];
  int flagged[4], n = 0;
  for (int i = 0; i < nve; ++i)
    if (splitEndpoint_[v[i]]) flagged[n++] = v[i];
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (midpoints_.find(edgeKey(flagged[i], flagged[j]))) return true;
  return false;
}

void BisectionRefiner::bisect(int e)
{
  if (dim_ == 2)
    bisectTriangle(e);
  else
    bisectTetrahedron(e);
  ++step_->numBisections;
}

void BisectionRefiner::bisectTriangle(int e)
{
  int* v = &verts_[static_cast<std::size_t>(e) * 3];
  const int v0 = v[0], v1 = v[1], v2 = v[2];
  const int m = midpoint(v0, v1);
  if (int* part = boundaryEdges_.find(edgeKey(v0, v1)); part && *part >= 0) {
    const int p = *part;
    *part = -1;
    boundaryEdges_.insert(edgeKey(v0, m), p);
    boundaryEdges_.insert(edgeKey(m, v1), p);
  }
  v[0] = v2, v[1] = v0, v[2] = m;  // first child stays in slot e (v is invalid after the insert)
  verts_.insert(verts_.end(), {v1, v2, m});
  gen_[e] += 1;
  gen_.push_back(gen_[e]);
  target_.push_back(target_[e]);
  ancestor_.push_back(ancestor_[e]);
}

void BisectionRefiner::bisectTetrahedron(int e)
{
  const int* v = &verts_[static_cast<std::size_t>(e) * 4];
  const int a = v[0], b = v[1], c = v[2], d = v[3];
  const int code = code_[e];
  const int ma = code & 3, mb = (code >> 2) & 3;
  const bool flag = (code & 16) != 0;
  const bool planar = ma == 0 && mb == 0;
  const int m = midpoint(a, b);

  // Split the boundary faces containing ab (NVB on the face: halves acm, bcm).
  for (int o : {c, d}) {
    int* part = boundaryFaces_.find(faceKey(a, b, o));
    if (!part || *part < 0) continue;
    const int p = *part;
    *part = -1;
    boundaryFaces_.insert(faceKey(a, o, m), p);
    boundaryFaces_.insert(faceKey(b, o, m), p);
    if (partCurved_[p]) {
      curvedEdges_.insert(edgeKey(a, m), p);
      curvedEdges_.insert(edgeKey(b, m), p);
      curvedEdges_.insert(edgeKey(o, m), p);
    }
  }

  const std::array<int, 2> Ma = ma == 0   ? std::array<int, 2>{a, c}
                                : ma == 1 ? std::array<int, 2>{a, d}
                                          : std::array<int, 2>{c, d};
  const std::array<int, 2> Mb = mb == 0   ? std::array<int, 2>{b, c}
                                : mb == 1 ? std::array<int, 2>{b, d}
                                          : std::array<int, 2>{c, d};
  // Marked edge of the new face cdm: cd, except for a flagged planar parent, where it is mc
  // (this is what makes the generations cycle like Maubach's tags 3 -> 2 -> 1).
  const std::array<int, 2> X = planar && flag ? std::array<int, 2>{m, c} : std::array<int, 2>{c, d};
  const bool childFlag = planar && !flag;

  const int wA[4] = {a, c, d, m};
  const std::array<int, 2> markA[4] = {X, {a, d}, {a, c}, Ma};
  const int wB[4] = {b, c, d, m};
  const std::array<int, 2> markB[4] = {X, {b, d}, {b, c}, Mb};

  const int child = static_cast<int>(gen_.size());
  verts_.resize(verts_.size() + 4);
  code_.push_back(0);
  setTetrahedron(e, wA, markA, childFlag);
  setTetrahedron(child, wB, markB, childFlag);
  gen_[e] += 1;
  gen_.push_back(gen_[e]);
  target_.push_back(target_[e]);
  ancestor_.push_back(ancestor_[e]);
}

const RefinementStep& BisectionRefiner::refine(const std::vector<int>& markedElements)
{
  const int ne = mesh_->numElements();
  target_.assign(ne, 0);
  for (int e : markedElements) {
    SC_THROW_IF(e < 0 || e >= ne, sc::core::InternalError,
                "BisectionRefiner::refine: marked element " << e << " out of range [0, " << ne
                                                            << ")");
    target_[e] = gen_[e] + 1;
  }
  return run();
}

const RefinementStep& BisectionRefiner::refineUniformly()
{
  const int ne = mesh_->numElements();
  target_.resize(ne);
  for (int e = 0; e < ne; ++e)
    target_[e] = gen_[e] + dim_;
  return run();
}

const RefinementStep& BisectionRefiner::run()
{
  const auto t0 = Clock::now();
  const int ne0 = mesh_->numElements();
  const int nv0 = mesh_->numVertices();
  history_.emplace_back();
  step_ = &history_.back();
  step_->numVerticesBefore = nv0;
  step_->numElementsBefore = ne0;
  ancestor_.resize(ne0);
  std::iota(ancestor_.begin(), ancestor_.end(), 0);
  midpoints_ = HashIndexMap<std::uint64_t>(16);
  splitEndpoint_.assign(nv0, 0);
  std::size_t expected = 0;
  for (int e = 0; e < ne0; ++e)
    expected += std::max(0, target_[e] - gen_[e]);
  verts_.reserve(verts_.size() + (dim_ + 1) * expected * 2);
  midpoints_.reserve(expected * (dim_ == 2 ? 2 : 3));

  // Sweep until no element contains a bisected edge or misses its target generation. Elements
  // appended during a sweep are visited in the same sweep.
  int passes = 0;
  for (bool changed = true; changed;) {
    changed = false;
    SC_THROW_IF(++passes > kMaxPasses, sc::core::InternalError,
                origin_ << ": bisection closure did not terminate after " << kMaxPasses
                        << " sweeps");
    for (int e = 0; e < static_cast<int>(gen_.size()); ++e)
      while (needsBisection(e)) {
        bisect(e);
        changed = true;
      }
  }
  const auto t1 = Clock::now();

  // History: parent of every new element, children of every old one.
  const int ne = static_cast<int>(gen_.size());
  step_->elementParent = ancestor_;
  step_->childrenPtr.assign(ne0 + 1, 0);
  for (int e = 0; e < ne; ++e)
    ++step_->childrenPtr[ancestor_[e] + 1];
  std::partial_sum(step_->childrenPtr.begin(), step_->childrenPtr.end(),
                   step_->childrenPtr.begin());
  step_->children.resize(ne);
  std::vector<int> fill(step_->childrenPtr.begin(), step_->childrenPtr.end() - 1);
  for (int e = 0; e < ne; ++e)
    step_->children[fill[ancestor_[e]]++] = e;

  if (step_->numBisections > 0) mesh_ = buildMesh();  // nothing marked: keep the same mesh
  step_->secondsBisection = seconds(t0, t1);
  step_->secondsMeshBuild = seconds(t1, Clock::now());
  // Release per-call memory.
  midpoints_ = HashIndexMap<std::uint64_t>(16);
  std::vector<int>().swap(ancestor_);
  std::vector<char>().swap(splitEndpoint_);
  return *step_;
}

BisectionRefiner::State BisectionRefiner::state() const
{
  State s;
  s.dim = dim_;
  s.coordinates = coords_;
  s.elementVertices = verts_;
  s.generations = gen_;
  s.codes = code_;
  boundaryEdges_.forEach([&](std::uint64_t key, int part) {
    s.boundaryEdges.push_back(key);
    s.boundaryEdgeParts.push_back(part);
  });
  boundaryFaces_.forEach([&](const FaceKey& key, int part) {
    s.boundaryFaces.insert(s.boundaryFaces.end(), key.begin(), key.end());
    s.boundaryFaceParts.push_back(part);
  });
  curvedEdges_.forEach([&](std::uint64_t key, int part) {
    s.curvedEdges.push_back(key);
    s.curvedEdgeParts.push_back(part);
  });
  return s;
}

void BisectionRefiner::restore(const State& s, const std::string& source)
{
  const std::size_t nv = s.coordinates.size() / (dim_ > 0 ? dim_ : 1);
  const std::size_t ne = s.elementVertices.size() / (dim_ + 1);
  const int parts = static_cast<int>(names_.size());
  auto bad = [&](const std::string& why) {
    SC_THROW_IF(true, sc::core::InputError,
                source << ": the refinement state is inconsistent: " << why);
  };
  if (s.dim != dim_)
    bad("dimension " + std::to_string(s.dim) + ", but the mesh of the deck has dimension " +
        std::to_string(dim_));
  if (s.coordinates.size() % dim_ != 0 || s.elementVertices.size() % (dim_ + 1) != 0 || ne == 0)
    bad("coordinate or element arrays of the wrong length");
  if (s.generations.size() != ne || (dim_ == 3 && s.codes.size() != ne) ||
      (dim_ == 2 && !s.codes.empty()))
    bad("per-element arrays of the wrong length");
  for (int v : s.elementVertices)
    if (v < 0 || static_cast<std::size_t>(v) >= nv) bad("an element vertex out of range");
  auto partsOk = [&](const std::vector<int>& p, std::size_t n) {
    if (p.size() != n) bad("boundary arrays of the wrong length");
    for (int q : p)
      if (q < -1 || q >= parts) bad("a boundary part id out of range");
  };
  partsOk(s.boundaryEdgeParts, s.boundaryEdges.size());
  partsOk(s.boundaryFaceParts, s.boundaryFaces.size() / 3);
  partsOk(s.curvedEdgeParts, s.curvedEdges.size());
  if (s.boundaryFaces.size() % 3 != 0) bad("boundary face array of the wrong length");
  for (std::uint64_t k : s.boundaryEdges)
    if ((k >> 32) >= nv || (k & 0xffffffffu) >= nv) bad("a boundary edge vertex out of range");
  for (std::uint64_t k : s.curvedEdges)
    if ((k >> 32) >= nv || (k & 0xffffffffu) >= nv) bad("a curved edge vertex out of range");
  for (int v : s.boundaryFaces)
    if (v < 0 || static_cast<std::size_t>(v) >= nv) bad("a boundary face vertex out of range");

  coords_ = s.coordinates;
  verts_ = s.elementVertices;
  gen_ = s.generations;
  code_ = s.codes;
  // Lookups do not depend on the order of insertion (only buildMesh's list order does, and
  // SimplexMesh assigns parts by key): the restored maps answer as the saved ones did.
  boundaryEdges_ = HashIndexMap<std::uint64_t>(s.boundaryEdges.size());
  for (std::size_t i = 0; i < s.boundaryEdges.size(); ++i)
    boundaryEdges_.insert(s.boundaryEdges[i], s.boundaryEdgeParts[i]);
  boundaryFaces_ = HashIndexMap<FaceKey>(s.boundaryFaceParts.size());
  for (std::size_t i = 0; i < s.boundaryFaceParts.size(); ++i)
    boundaryFaces_.insert(
        {s.boundaryFaces[3 * i], s.boundaryFaces[3 * i + 1], s.boundaryFaces[3 * i + 2]},
        s.boundaryFaceParts[i]);
  curvedEdges_ = HashIndexMap<std::uint64_t>(s.curvedEdges.size());
  for (std::size_t i = 0; i < s.curvedEdges.size(); ++i)
    curvedEdges_.insert(s.curvedEdges[i], s.curvedEdgeParts[i]);
  history_.clear();
  mesh_ = buildMesh();
}

Teuchos::RCP<const SimplexMesh> BisectionRefiner::buildMesh() const
{
  std::vector<int> bfv, bpart;
  if (dim_ == 2) {
    boundaryEdges_.forEach([&](std::uint64_t key, int part) {
      if (part < 0) return;
      bfv.push_back(static_cast<int>(key >> 32));
      bfv.push_back(static_cast<int>(key & 0xffffffffu));
      bpart.push_back(part);
    });
  } else {
    boundaryFaces_.forEach([&](const FaceKey& key, int part) {
      if (part < 0) return;
      bfv.insert(bfv.end(), key.begin(), key.end());
      bpart.push_back(part);
    });
  }
  // SimplexMesh orders each element positively (the refinement order is kept here).
  return Teuchos::rcp(new SimplexMesh(dim_, coords_, verts_, bfv, bpart, names_, origin_));
}

}  // namespace sc::mesh
