#include <sc/mesh/SimplexMesh.hpp>

#include <sc/core/Error.hpp>
#include <sc/mesh/HashIndexMap.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace sc::mesh {

namespace {

constexpr double kPi = 3.14159265358979323846;

inline void sub(const double* a, const double* b, int d, double* out)
{
  for (int i = 0; i < d; ++i)
    out[i] = a[i] - b[i];
}
inline std::array<double, 3> cross(const double* a, const double* b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const double* a, int d)
{
  double s = 0;
  for (int i = 0; i < d; ++i)
    s += a[i] * a[i];
  return std::sqrt(s);
}

}  // namespace

SimplexMesh::SimplexMesh(int dim, std::vector<double> coordinates, std::vector<int> elementVertices,
                         const std::vector<int>& boundaryFaceVertices,
                         const std::vector<int>& boundaryFacePart,
                         std::vector<std::string> boundaryNames, std::string origin,
                         const Labels* labels)
    : dim_(dim), origin_(std::move(origin)), coords_(std::move(coordinates)),
      elemVerts_(std::move(elementVertices)), boundaryNames_(std::move(boundaryNames)),
      labels_(labels)
{
  SC_THROW_IF(dim_ != 2 && dim_ != 3, sc::core::InputError,
              origin_ << ": mesh dimension " << dim_ << " is not supported (valid: 2, 3)");
  SC_THROW_IF(coords_.size() % dim_ != 0 || elemVerts_.size() % (dim_ + 1) != 0,
              sc::core::InternalError, origin_ << ": inconsistent coordinate/element array sizes");
  SC_THROW_IF(numElements() == 0, sc::core::InputError,
              origin_ << ": the mesh has no " << (dim_ == 2 ? "triangles" : "tetrahedra"));
  const int nv = numVertices();
  for (std::size_t i = 0; i < elemVerts_.size(); ++i)
    SC_THROW_IF(elemVerts_[i] < 0 || elemVerts_[i] >= nv, sc::core::InputError,
                origin_ << ": element " << i / (dim_ + 1) << " refers to vertex " << elemVerts_[i]
                        << " but the mesh has " << nv << " vertices");
  orientAndMeasureElements();
  buildFaces();
  checkFolds();
  assignBoundaryParts(boundaryFaceVertices, boundaryFacePart);
  checkHangingNodes();
  buildVertexElements();
  buildEdges();
  boundaryVertex_.assign(numVertices(), 0);
  for (int f : boundaryFaces_)
    for (int i = 0; i < dim_; ++i)
      boundaryVertex_[faceVertices(f)[i]] = 1;
  labels_ = nullptr;
}

std::string SimplexMesh::vertexLabel(int v) const
{
  if (labels_ && static_cast<std::size_t>(v) < labels_->vertex.size())
    return "node " + std::to_string(labels_->vertex[v]);
  return "vertex " + std::to_string(v);
}

std::string SimplexMesh::elementLabel(int e) const
{
  if (labels_ && static_cast<std::size_t>(e) < labels_->element.size())
    return "element " + std::to_string(labels_->element[e]);
  return "element " + std::to_string(e);
}

std::vector<int> SimplexMesh::elementsWithAllVerticesOnBoundary() const
{
  std::vector<int> out;
  for (int e = 0; e < numElements(); ++e) {
    const int* v = elementVertices(e);
    bool all = true;
    for (int i = 0; i <= dim_; ++i)
      all = all && boundaryVertex_[v[i]];
    if (all) out.push_back(e);
  }
  return out;
}

void SimplexMesh::buildEdges()
{
  const int ne = numElements();
  if (dim_ == 2) {  // edges are the faces; shards edge s = side s
    edgeVerts_ = faceVerts_;
    elemEdges_.resize(static_cast<std::size_t>(ne) * 3);
    for (int e = 0; e < ne; ++e)
      for (int s = 0; s < 3; ++s)
        elemEdges_[3 * static_cast<std::size_t>(e) + s] = sideFace(e, s);
    return;
  }
  constexpr int pairs[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  HashIndexMap<std::uint64_t> map(static_cast<std::size_t>(numVertices()) * 7);
  elemEdges_.resize(static_cast<std::size_t>(ne) * 6);
  for (int e = 0; e < ne; ++e) {
    const int* v = elementVertices(e);
    for (int k = 0; k < 6; ++k) {
      const int a = std::min(v[pairs[k][0]], v[pairs[k][1]]),
                b = std::max(v[pairs[k][0]], v[pairs[k][1]]);
      auto [val, inserted] = map.insert(edgeKey(a, b), numEdges());
      if (inserted) edgeVerts_.insert(edgeVerts_.end(), {a, b});
      elemEdges_[6 * static_cast<std::size_t>(e) + k] = *val;
    }
  }
}

double SimplexMesh::signedMeasure(const int* v) const
{
  const double* x0 = vertex(v[0]);
  double a[3], b[3], c[3];
  sub(vertex(v[1]), x0, dim_, a);
  sub(vertex(v[2]), x0, dim_, b);
  if (dim_ == 2) return 0.5 * (a[0] * b[1] - a[1] * b[0]);
  sub(vertex(v[3]), x0, dim_, c);
  const auto axb = cross(a, b);
  return (axb[0] * c[0] + axb[1] * c[1] + axb[2] * c[2]) / 6.0;
}

std::string SimplexMesh::describeElement(int e) const
{
  std::ostringstream os;
  os << elementLabel(e) << " (";
  const int* v = elementVertices(e);
  for (int i = 0; i <= dim_; ++i) {
    os << (i ? ", " : "") << vertexLabel(v[i]) << " (";
    for (int k = 0; k < dim_; ++k)
      os << (k ? ", " : "") << vertex(v[i])[k];
    os << ")";
  }
  os << ")";
  return os.str();
}

std::string SimplexMesh::describeFace(const int* v) const
{
  std::ostringstream os;
  os << (dim_ == 2 ? "edge" : "face") << " (";
  for (int i = 0; i < dim_; ++i) {
    os << (i ? ", " : "") << vertexLabel(v[i]) << " (";
    for (int k = 0; k < dim_; ++k)
      os << (k ? ", " : "") << vertex(v[i])[k];
    os << ")";
  }
  os << ")";
  return os.str();
}

void SimplexMesh::orientAndMeasureElements()
{
  const int ne = numElements(), nve = dim_ + 1;
  elemMeasure_.resize(ne);
  elemDiameter_.resize(ne);
  for (int e = 0; e < ne; ++e) {
    int* v = &elemVerts_[static_cast<std::size_t>(e) * nve];
    double diam2 = 0;
    for (int i = 0; i < nve; ++i)
      for (int j = i + 1; j < nve; ++j) {
        double d[3], s = 0;
        sub(vertex(v[i]), vertex(v[j]), dim_, d);
        for (int k = 0; k < dim_; ++k)
          s += d[k] * d[k];
        diam2 = std::max(diam2, s);
      }
    const double diam = std::sqrt(diam2);
    double m = signedMeasure(v);
    // Relative test: a sliver whose measure is 1e-12 of its diameter's cube is numerically flat.
    SC_THROW_IF(!(std::abs(m) > 1e-12 * (dim_ == 2 ? diam2 : diam2 * diam)), sc::core::InputError,
                origin_ << ": degenerate " << describeElement(e) << " has measure " << m);
    if (m < 0) {  // reorder to positive orientation (file meshes may come clockwise)
      std::swap(v[dim_ - 1], v[dim_]);
      m = -m;
    }
    elemMeasure_[e] = m;
    elemDiameter_[e] = diam;
  }
}

void SimplexMesh::buildFaces()
{
  const int ne = numElements(), nve = dim_ + 1;
  elemFaces_.assign(static_cast<std::size_t>(ne) * nve, -1);
  faceVerts_.clear();
  faceElems_.clear();
  // Faces = ((d+1) ne + boundary faces) / 2: leave room for the boundary so the table never grows.
  const std::size_t expected = static_cast<std::size_t>(ne) * (dim_ + 1) / 2 + ne / 4 + 16;
  faceVerts_.reserve(expected * dim_);
  faceElems_.reserve(expected);
  auto addIncidence = [&](int e, int i, int f, bool isNew, const int* fv) {
    elemFaces_[static_cast<std::size_t>(e) * nve + i] = f;
    if (isNew) {
      faceVerts_.insert(faceVerts_.end(), fv, fv + dim_);
      faceElems_.push_back({e, -1});
    } else {
      auto& fe = faceElems_[f];
      if (fe[1] >= 0) {
        std::ostringstream os;
        os << origin_ << ": non-conforming mesh: the " << describeFace(fv)
           << " is shared by more than two elements (" << elementLabel(fe[0]) << ", "
           << elementLabel(fe[1]) << ", " << elementLabel(e) << ")";
        throw sc::core::InputError(os.str());
      }
      fe[1] = e;
    }
  };
  if (dim_ == 2) {
    HashIndexMap<std::uint64_t> map(expected);
    for (int e = 0; e < ne; ++e) {
      const int* v = elementVertices(e);
      for (int i = 0; i < 3; ++i) {
        int a = v[(i + 1) % 3], b = v[(i + 2) % 3];
        if (a > b) std::swap(a, b);
        const int fv[2] = {a, b};
        auto [val, inserted] = map.insert(edgeKey(a, b), numFaces());
        addIncidence(e, i, *val, inserted, fv);
      }
    }
  } else {
    HashIndexMap<FaceKey> map(expected);
    for (int e = 0; e < ne; ++e) {
      const int* v = elementVertices(e);
      for (int i = 0; i < 4; ++i) {
        int w[3], k = 0;
        for (int j = 0; j < 4; ++j)
          if (j != i) w[k++] = v[j];
        const FaceKey key = faceKey(w[0], w[1], w[2]);
        auto [val, inserted] = map.insert(key, numFaces());
        addIncidence(e, i, *val, inserted, key.data());
      }
    }
  }
  // Face measures and normals (out of faceElems_[f][0]).
  const int nf = numFaces();
  faceMeasure_.resize(nf);
  faceNormal_.resize(static_cast<std::size_t>(nf) * dim_);
  for (int f = 0; f < nf; ++f) {
    const int* fv = faceVertices(f);
    double n[3] = {0, 0, 0}, meas;
    double a[3], b[3];
    sub(vertex(fv[1]), vertex(fv[0]), dim_, a);
    if (dim_ == 2) {
      meas = norm(a, 2);
      n[0] = a[1] / meas;
      n[1] = -a[0] / meas;
    } else {
      sub(vertex(fv[2]), vertex(fv[0]), 3, b);
      const auto c = cross(a, b);
      const double len = norm(c.data(), 3);
      meas = 0.5 * len;
      for (int k = 0; k < 3; ++k)
        n[k] = c[k] / len;
    }
    // Orient away from the vertex of element faceElems_[f][0] opposite this face.
    const int e = faceElems_[f][0];
    const int* ev = elementVertices(e);
    const int* ef = elementFaces(e);
    const int local = static_cast<int>(std::find(ef, ef + nve, f) - ef);
    double d[3];
    sub(vertex(ev[local]), vertex(fv[0]), dim_, d);
    double s = 0;
    for (int k = 0; k < dim_; ++k)
      s += n[k] * d[k];
    if (s > 0)
      for (int k = 0; k < dim_; ++k)
        n[k] = -n[k];
    faceMeasure_[f] = meas;
    for (int k = 0; k < dim_; ++k)
      faceNormal_[static_cast<std::size_t>(f) * dim_ + k] = n[k];
  }
}

void SimplexMesh::checkFolds() const
{
  // Two elements sharing a face must lie on opposite sides of it; otherwise they overlap
  // (an inverted element in a file, or a refinement bug).
  const int nve = dim_ + 1;
  for (int f = 0; f < numFaces(); ++f) {
    const int e1 = faceElems_[f][1];
    if (e1 < 0) continue;
    const int* ef = elementFaces(e1);
    const int local = static_cast<int>(std::find(ef, ef + nve, f) - ef);
    const int* fv = faceVertices(f);
    double d[3];
    sub(vertex(elementVertices(e1)[local]), vertex(fv[0]), dim_, d);
    const auto n = faceNormal(f);
    double s = 0;
    for (int k = 0; k < dim_; ++k)
      s += n[k] * d[k];
    SC_THROW_IF(!(s > 0), sc::core::InputError,
                origin_ << ": inverted or overlapping elements: "
                        << describeElement(faceElems_[f][0]) << " and " << describeElement(e1)
                        << " lie on the same side of their common " << describeFace(fv));
  }
}

void SimplexMesh::assignBoundaryParts(const std::vector<int>& bfv, const std::vector<int>& bpart)
{
  const int nf = numFaces();
  faceBoundary_.assign(nf, -1);
  SC_THROW_IF(bfv.size() != bpart.size() * dim_, sc::core::InternalError,
              origin_ << ": boundary face arrays have inconsistent sizes");
  // Lookup of the listed faces among the mesh faces by key.
  std::vector<int> faceOf(bpart.size(), -1);
  std::size_t nb = 0;
  for (int f = 0; f < nf; ++f)
    nb += isBoundaryFace(f);
  if (dim_ == 2) {
    HashIndexMap<std::uint64_t> map(nb);
    for (int f = 0; f < nf; ++f)
      if (isBoundaryFace(f)) map.insert(edgeKey(faceVerts_[2 * f], faceVerts_[2 * f + 1]), f);
    for (std::size_t i = 0; i < bpart.size(); ++i)
      if (const int* p = map.find(edgeKey(bfv[2 * i], bfv[2 * i + 1]))) faceOf[i] = *p;
  } else {
    HashIndexMap<FaceKey> map(nb);
    for (int f = 0; f < nf; ++f)
      if (isBoundaryFace(f)) {
        const int* v = faceVertices(f);
        map.insert(faceKey(v[0], v[1], v[2]), f);
      }
    for (std::size_t i = 0; i < bpart.size(); ++i)
      if (const int* p = map.find(faceKey(bfv[3 * i], bfv[3 * i + 1], bfv[3 * i + 2])))
        faceOf[i] = *p;
  }
  for (std::size_t i = 0; i < bpart.size(); ++i) {
    const int part = bpart[i];
    SC_THROW_IF(part < 0 || part >= numBoundaryParts(), sc::core::InternalError,
                origin_ << ": boundary part id " << part << " out of range");
    if (faceOf[i] < 0) {
      std::vector<int> v(bfv.begin() + i * dim_, bfv.begin() + (i + 1) * dim_);
      std::sort(v.begin(), v.end());
      SC_THROW_IF(true, sc::core::InputError,
                  origin_ << ": the " << describeFace(v.data()) << " of boundary part '"
                          << boundaryNames_[part]
                          << "' is not a boundary face of the mesh (interior face, or not a face "
                             "of any element: non-conforming boundary mesh)");
    }
    faceBoundary_[faceOf[i]] = part;
  }
  int unnamed = -1;
  for (int f = 0; f < nf; ++f) {
    if (!isBoundaryFace(f)) continue;
    if (faceBoundary_[f] < 0) {
      if (unnamed < 0) {
        auto it = std::find(boundaryNames_.begin(), boundaryNames_.end(), "Unnamed");
        unnamed = static_cast<int>(it - boundaryNames_.begin());
        if (it == boundaryNames_.end()) boundaryNames_.push_back("Unnamed");
      }
      faceBoundary_[f] = unnamed;
    }
    boundaryFaces_.push_back(f);
  }
}

void SimplexMesh::checkHangingNodes() const
{
  // A hanging node makes faces of the element mesh appear as boundary faces although they are
  // inside the domain: a vertex v lying on a boundary-surface edge (a, b) with the edges (a, v)
  // and (v, b) also on the boundary surface. Checked on the graph of boundary-surface edges
  // (cost: sum of squared vertex degrees on the boundary).
  HashIndexMap<std::uint64_t> edges(boundaryFaces_.size() * dim_);
  std::vector<std::pair<int, int>> list;
  for (int f : boundaryFaces_) {
    const int* v = faceVertices(f);
    for (int i = 0; i < dim_; ++i)
      for (int j = i + 1; j < dim_; ++j)
        if (edges.insert(edgeKey(v[i], v[j]), 0).second) list.emplace_back(v[i], v[j]);
  }
  const int nv = numVertices();
  std::vector<int> ptr(nv + 1, 0), adj(2 * list.size());
  for (auto [a, b] : list) {
    ++ptr[a + 1];
    ++ptr[b + 1];
  }
  std::partial_sum(ptr.begin(), ptr.end(), ptr.begin());
  std::vector<int> fill(ptr.begin(), ptr.end() - 1);
  for (auto [a, b] : list) {
    adj[fill[a]++] = b;
    adj[fill[b]++] = a;
  }
  for (auto [a, b] : list) {
    const double* xa = vertex(a);
    const double* xb = vertex(b);
    double ab[3];
    sub(xb, xa, dim_, ab);
    const double ab2 = std::pow(norm(ab, dim_), 2);
    for (int k = ptr[a]; k < ptr[a + 1]; ++k) {
      const int v = adj[k];
      if (v == b || !edges.find(edgeKey(v, b))) continue;
      double av[3];
      sub(vertex(v), xa, dim_, av);
      double t = 0;
      for (int i = 0; i < dim_; ++i)
        t += av[i] * ab[i];
      t /= ab2;
      double dist2 = 0;
      for (int i = 0; i < dim_; ++i)
        dist2 += std::pow(av[i] - t * ab[i], 2);
      SC_THROW_IF(t > 1e-8 && t < 1 - 1e-8 && dist2 < 1e-16 * ab2, sc::core::InputError,
                  origin_ << ": non-conforming mesh: hanging node: " << vertexLabel(v)
                          << " lies inside the edge (" << vertexLabel(a) << ", " << vertexLabel(b)
                          << ") of a neighbouring element");
    }
  }
}

void SimplexMesh::buildVertexElements()
{
  const int nv = numVertices(), ne = numElements(), nve = dim_ + 1;
  vertElemPtr_.assign(nv + 1, 0);
  for (int v : elemVerts_)
    ++vertElemPtr_[v + 1];
  std::partial_sum(vertElemPtr_.begin(), vertElemPtr_.end(), vertElemPtr_.begin());
  vertElems_.resize(elemVerts_.size());
  std::vector<int> fill(vertElemPtr_.begin(), vertElemPtr_.end() - 1);
  for (int e = 0; e < ne; ++e)
    for (int i = 0; i < nve; ++i)
      vertElems_[fill[elemVerts_[static_cast<std::size_t>(e) * nve + i]]++] = e;
}

std::array<double, 3> SimplexMesh::faceNormal(int f) const
{
  std::array<double, 3> n{0, 0, 0};
  for (int k = 0; k < dim_; ++k)
    n[k] = faceNormal_[static_cast<std::size_t>(f) * dim_ + k];
  return n;
}

int SimplexMesh::boundaryId(const std::string& name) const
{
  auto it = std::find(boundaryNames_.begin(), boundaryNames_.end(), name);
  if (it == boundaryNames_.end()) {
    std::ostringstream os;
    os << origin_ << ": unknown boundary name '" << name << "'; valid names:";
    for (const auto& n : boundaryNames_)
      os << " '" << n << "'";
    throw sc::core::InputError(os.str());
  }
  return static_cast<int>(it - boundaryNames_.begin());
}

bool SimplexMesh::hasBoundary(const std::string& name) const
{
  return std::find(boundaryNames_.begin(), boundaryNames_.end(), name) != boundaryNames_.end();
}

std::vector<int> SimplexMesh::boundaryFacesOf(const std::string& name) const
{
  const int id = boundaryId(name);
  std::vector<int> out;
  for (int f : boundaryFaces_)
    if (faceBoundary_[f] == id) out.push_back(f);
  return out;
}

double SimplexMesh::boundaryMeasure(const std::string& name) const
{
  double s = 0;
  for (int f : boundaryFacesOf(name))
    s += faceMeasure_[f];
  return s;
}

double SimplexMesh::measure() const
{
  // Pairwise-free but compensated summation: refinement tests compare measures to 1e-12.
  double s = 0, c = 0;
  for (double m : elemMeasure_) {
    const double y = m - c, t = s + y;
    c = (t - s) - y;
    s = t;
  }
  return s;
}

double SimplexMesh::meshSize() const
{
  return *std::max_element(elemDiameter_.begin(), elemDiameter_.end());
}

std::vector<double> SimplexMesh::elementAnglesDeg(int e) const
{
  const int* v = elementVertices(e);
  std::vector<double> out;
  if (dim_ == 2) {
    for (int i = 0; i < 3; ++i) {
      double a[2], b[2];
      sub(vertex(v[(i + 1) % 3]), vertex(v[i]), 2, a);
      sub(vertex(v[(i + 2) % 3]), vertex(v[i]), 2, b);
      const double c = (a[0] * b[0] + a[1] * b[1]) / (norm(a, 2) * norm(b, 2));
      out.push_back(std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi);
    }
    return out;
  }
  // Outward unit normals of the faces opposite each vertex.
  std::array<std::array<double, 3>, 4> n;
  for (int k = 0; k < 4; ++k) {
    int w[3], j = 0;
    for (int i = 0; i < 4; ++i)
      if (i != k) w[j++] = v[i];
    double a[3], b[3], d[3];
    sub(vertex(w[1]), vertex(w[0]), 3, a);
    sub(vertex(w[2]), vertex(w[0]), 3, b);
    sub(vertex(v[k]), vertex(w[0]), 3, d);
    auto c = cross(a, b);
    const double len = norm(c.data(), 3);
    const double s = (c[0] * d[0] + c[1] * d[1] + c[2] * d[2]) > 0 ? -1.0 : 1.0;
    for (int i = 0; i < 3; ++i)
      n[k][i] = s * c[i] / len;
  }
  // Dihedral angle at edge (i, j) is pi minus the angle between the outward normals of the two
  // faces containing the edge (those opposite the other two vertices k, l).
  const int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  for (const auto& ed : edges) {
    int kl[2], j = 0;
    for (int i = 0; i < 4; ++i)
      if (i != ed[0] && i != ed[1]) kl[j++] = i;
    const double c =
        -(n[kl[0]][0] * n[kl[1]][0] + n[kl[0]][1] * n[kl[1]][1] + n[kl[0]][2] * n[kl[1]][2]);
    out.push_back(std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi);
  }
  return out;
}

double SimplexMesh::minAngleDeg() const
{
  double m = 180.0;
  for (int e = 0; e < numElements(); ++e)
    for (double a : elementAnglesDeg(e))
      m = std::min(m, a);
  return m;
}

long SimplexMesh::eulerCharacteristic() const
{
  const long V = numVertices(), T = numElements(), F = numFaces();
  if (dim_ == 2) return V - F + T;
  return V - numEdges() + F - T;
}

}  // namespace sc::mesh
