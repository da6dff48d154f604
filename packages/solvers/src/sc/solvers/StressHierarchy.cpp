// Prolongation and smoother patches for the multigrid of the stress block (see the header).

#include <sc/solvers/StressHierarchy.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>

#include <sc/core/Error.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/Partitioning.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::solvers {

namespace {
using GO = Tpetra::Map<>::global_ordinal_type;

Teuchos::RCP<const Map> ownedStressMap(const disc::MixedElasticitySpace& s,
                                       const Teuchos::RCP<const Teuchos::Comm<int>>& comm)
{
  std::vector<GO> gids;
  for (long long g : s.ownedDofs())
    if (g < s.numStressDofs()) gids.push_back(g);
  return Teuchos::rcp(new Map(s.numStressDofs(), Teuchos::ArrayView<const GO>(gids), 0, comm));
}

// Owner rank of element e (its first displacement DOF belongs to it alone).
int elementOwner(const disc::MixedElasticitySpace& s, int e)
{
  return s.dofOwner(s.elementDofs(e)[s.displacementOffset(0)]);
}
// The σ DOFs of the fine elements inside each coarse element this rank handles (the owner of
// its lowest-numbered fine element), split at the coarse element's boundary: a fine face lies on
// it when it is on the domain boundary or its other element has another parent
// (MultigridLevel::coarseElements).
std::vector<MultigridLevel::CoarseElement> coarseElementDofs(const disc::MixedElasticitySpace& fine,
                                                             const std::vector<int>& parent,
                                                             int coarseElements)
{
  const auto& m = fine.mesh();
  const int d = fine.dim(), nRT = fine.stressBasisSize(), ne = m.numElements();
  std::vector<int> first(coarseElements, -1);
  for (int e = 0; e < ne; ++e)
    if (first[parent[e]] < 0) first[parent[e]] = e;
  std::vector<int> slot(coarseElements, -1);
  std::vector<MultigridLevel::CoarseElement> out;
  for (int c = 0; c < coarseElements; ++c)
    if (first[c] >= 0 && elementOwner(fine, first[c]) == fine.rank()) {
      slot[c] = static_cast<int>(out.size());
      out.emplace_back();
    }
  std::vector<char> onBoundary(nRT);
  for (int e = 0; e < ne; ++e) {
    const int s = slot[parent[e]];
    if (s < 0) continue;
    std::fill(onBoundary.begin(), onBoundary.end(), 0);
    for (int lf = 0; lf <= d; ++lf) {
      const auto fe = m.faceElements(m.elementFaces(e)[lf]);
      const int other = fe[0] == e ? fe[1] : fe[0];
      if (other < 0 || parent[other] != parent[e])
        for (int a : fine.stressFaceLocalDofs(lf))
          onBoundary[a] = 1;
    }
    const long long* ed = fine.elementDofs(e);
    for (int i = 0; i < d; ++i)
      for (int a = 0; a < nRT; ++a)
        (onBoundary[a] ? out[s].boundary : out[s].interior).push_back(ed[fine.stressOffset(i) + a]);
  }
  for (auto& c : out)
    for (auto* v : {&c.interior, &c.boundary}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
  return out;
}
}  // namespace

Teuchos::RCP<CrsMatrix> stressProlongation(const disc::MixedElasticitySpace& coarse,
                                           const disc::MixedElasticitySpace& fine,
                                           const std::vector<int>& parent,
                                           const Teuchos::RCP<const Teuchos::Comm<int>>& comm)
{
  const auto& fm = fine.mesh();
  SC_THROW_IF(static_cast<int>(parent.size()) != fm.numElements(), core::InternalError,
              "stressProlongation: " << parent.size() << " parents for " << fm.numElements()
                                     << " fine elements");
  SC_THROW_IF(coarse.degree() != fine.degree() || coarse.dim() != fine.dim(), core::InternalError,
              "stressProlongation: the spaces differ in degree or dimension");
  const int d = fine.dim(), k = fine.degree(), nRT = fine.stressBasisSize();
  const int rank = fine.rank();
  auto rowMap = ownedStressMap(fine, comm);
  auto domainMap = ownedStressMap(coarse, comm);
  auto P = Teuchos::rcp(new CrsMatrix(rowMap, nRT));
  std::vector<char> done(fine.numStressDofs(), 0);
  disc::ElementValues evF(fine, 2 * k + 2), evC(coarse, 2 * k + 2);
  std::vector<double> pts, G(static_cast<std::size_t>(nRT) * nRT),
      C(static_cast<std::size_t>(nRT) * nRT);
  std::vector<int> ipiv(nRT);
  Teuchos::LAPACK<int, double> lapack;
  for (int f = 0; f < fm.numElements(); ++f) {
    const long long* fd = fine.elementDofs(f);
    bool needed = false;
    for (int i = 0; i < d && !needed; ++i)
      for (int a = 0; a < nRT && !needed; ++a) {
        const long long g = fd[fine.stressOffset(i) + a];
        needed = !done[g] && fine.dofOwner(g) == rank;
      }
    if (!needed) continue;
    evF.reinit(f);
    const int nq = evF.numPoints();
    pts.assign(evF.point(0), evF.point(0) + 3 * nq);
    evC.reinitAtPoints(parent[f], pts);
    // G c = C: G_ab = (φ_a, φ_b)_f, C_ab = (φ_a, ψ_b)_f; column-major for LAPACK.
    std::fill(G.begin(), G.end(), 0.0);
    std::fill(C.begin(), C.end(), 0.0);
    for (int q = 0; q < nq; ++q) {
      const double w = evF.weight(q);
      for (int a = 0; a < nRT; ++a)
        for (int b = 0; b < nRT; ++b) {
          double gab = 0.0, cab = 0.0;
          for (int c = 0; c < d; ++c) {
            gab += evF.stress(a, q, c) * evF.stress(b, q, c);
            cab += evF.stress(a, q, c) * evC.stress(b, q, c);
          }
          G[b * nRT + a] += w * gab;
          C[b * nRT + a] += w * cab;
        }
    }
    int info = 0;
    lapack.GESV(nRT, nRT, G.data(), nRT, ipiv.data(), C.data(), nRT, &info);
    SC_THROW_IF(info != 0, core::InternalError,
                "stressProlongation: singular RT mass on element " << f << " (info " << info
                                                                   << ")");
    const long long* cd = coarse.elementDofs(parent[f]);
    double scale = 0.0;
    for (double v : C)
      scale = std::max(scale, std::abs(v));
    for (int i = 0; i < d; ++i)
      for (int a = 0; a < nRT; ++a) {
        const long long g = fd[fine.stressOffset(i) + a];
        if (done[g] || fine.dofOwner(g) != rank) continue;
        done[g] = 1;
        std::vector<GO> cols;
        std::vector<double> vals;
        for (int b = 0; b < nRT; ++b) {
          const double v = C[b * nRT + a];
          if (std::abs(v) > 1e-13 * scale) {
            cols.push_back(cd[coarse.stressOffset(i) + b]);
            vals.push_back(v);
          }
        }
        P->insertGlobalValues(g, Teuchos::ArrayView<const GO>(cols),
                              Teuchos::ArrayView<const double>(vals));
      }
  }
  P->fillComplete(domainMap, rowMap);
  return P;
}

std::vector<std::vector<long long>> stressPatches(const disc::MixedElasticitySpace& space)
{
  const auto& m = space.mesh();
  const int d = space.dim(), nRT = space.stressBasisSize();
  const int ne = m.numElements();
  // The patch entities: vertices in 2D (one local vertex), edges in 3D (two local vertices), as
  // (key, element, local vertex mask) sorted by key, so that each entity's star is one run.
  struct Incidence {
    std::uint64_t key;
    int element;
    unsigned mask;  // bit j: local vertex j belongs to the entity
  };
  std::vector<Incidence> inc;
  inc.reserve(static_cast<std::size_t>(ne) * (d == 2 ? 3 : 6));
  for (int e = 0; e < ne; ++e) {
    const int* ev = m.elementVertices(e);
    if (d == 2) {
      for (int j = 0; j < 3; ++j)
        inc.push_back({static_cast<std::uint64_t>(ev[j]), e, 1u << j});
    } else {
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
          const auto lo = static_cast<std::uint64_t>(std::min(ev[i], ev[j]));
          const auto hi = static_cast<std::uint64_t>(std::max(ev[i], ev[j]));
          inc.push_back({(lo << 32) | hi, e, (1u << i) | (1u << j)});
        }
    }
  }
  std::sort(inc.begin(), inc.end(), [](const Incidence& x, const Incidence& y) {
    return x.key != y.key ? x.key < y.key : x.element < y.element;
  });
  // local RT DOFs on some face (the others are interior)
  std::vector<char> onFace(nRT, 0);
  for (int lf = 0; lf <= d; ++lf)
    for (int a : space.stressFaceLocalDofs(lf))
      onFace[a] = 1;
  std::vector<std::vector<long long>> patches;
  for (std::size_t begin = 0, end = 0; begin < inc.size(); begin = end) {
    end = begin;
    while (end < inc.size() && inc[end].key == inc[begin].key)
      ++end;
    // the owner of the lowest-numbered element of the star smooths it (sorted by element)
    if (elementOwner(space, inc[begin].element) != space.rank()) continue;
    std::vector<long long> p;
    for (std::size_t s = begin; s < end; ++s) {
      const long long* ed = space.elementDofs(inc[s].element);
      for (int i = 0; i < d; ++i) {
        for (int a = 0; a < nRT; ++a)
          if (!onFace[a]) p.push_back(ed[space.stressOffset(i) + a]);
        // face lf is opposite local vertex lf: it contains the entity iff lf is not one of its
        // vertices
        for (int lf = 0; lf <= d; ++lf)
          if (!(inc[s].mask & (1u << lf)))
            for (int a : space.stressFaceLocalDofs(lf))
              p.push_back(ed[space.stressOffset(i) + a]);
      }
    }
    std::sort(p.begin(), p.end());
    p.erase(std::unique(p.begin(), p.end()), p.end());
    patches.push_back(std::move(p));
  }
  return patches;
}

StressHierarchy::StressHierarchy(int degree, Teuchos::RCP<const Teuchos::Comm<int>> comm,
                                 double ratio)
    : degree_(degree), comm_(std::move(comm)), ratio_(ratio)
{
}

StressHierarchy::~StressHierarchy() = default;

void StressHierarchy::addMesh(Teuchos::RCP<const mesh::SimplexMesh> mesh,
                              const std::vector<int>& parent)
{
  SC_THROW_IF(!meshes_.empty() && static_cast<int>(parent.size()) != mesh->numElements(),
              core::InternalError,
              "StressHierarchy: " << parent.size() << " parents for " << mesh->numElements()
                                  << " elements");
  meshes_.push_back(std::move(mesh));
  parents_.push_back(meshes_.size() == 1 ? std::vector<int>() : parent);
}

int StressHierarchy::meshElements(int i) const { return meshes_.at(i)->numElements(); }

std::vector<MultigridLevel> StressHierarchy::levels(const disc::MixedElasticitySpace& finest) const
{
  SC_THROW_IF(meshes_.empty() || &finest.mesh() != meshes_.back().get(), core::InternalError,
              "StressHierarchy::levels: the space is not on the last mesh added");
  const int n = static_cast<int>(meshes_.size());
  // finest first while choosing
  std::vector<int> pick = {n - 1};
  for (int i = n - 2; i >= 0; --i)
    if (ratio_ * meshes_[i]->numElements() <= meshes_[pick.back()]->numElements())
      pick.push_back(i);
  if (pick.size() > 1)
    pick.back() = 0;  // the first mesh is the coarsest level (fewer elements: the ratio holds)
  std::reverse(pick.begin(), pick.end());
  chosen_ = pick;
  std::vector<MultigridLevel> out(pick.size());
  Teuchos::RCP<const disc::MixedElasticitySpace> previous;
  for (std::size_t l = 0; l < pick.size(); ++l) {
    const int i = pick[l];
    Teuchos::RCP<const disc::MixedElasticitySpace> space;
    if (l + 1 == pick.size())
      space = Teuchos::rcpFromRef(finest);
    else
      // partitioned and numbered as sc::assembly::MixedElasticitySystem does (METIS)
      space = Teuchos::rcp(new disc::MixedElasticitySpace(
          meshes_[i], degree_, mesh::partitionElements(*meshes_[i], *comm_), comm_->getRank()));
    if (l > 0) {
      // parent in mesh pick[l − 1] of every element of mesh i, composed over the meshes between
      std::vector<int> parent = parents_[i];
      for (int j = i - 1; j > pick[l - 1]; --j)
        for (int& p : parent)
          p = parents_[j][p];
      out[l].prolongation = stressProlongation(*previous, *space, parent, comm_);
      out[l].patches = stressPatches(*space);
      out[l].coarseElements = coarseElementDofs(*space, parent, previous->mesh().numElements());
    }
    previous = space;
  }
  return out;
}

}  // namespace sc::solvers
