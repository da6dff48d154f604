// The contact state carried to the next mesh (nested iteration) through the refinement history,
// with the friction history of load steps (docs/theory.md §"Load steps", docs/contact.md).
#include "sc/contact/StateTransfer.hpp"

#include <algorithm>
#include <utility>

#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/disc/FaceFit.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::contact {

void transferContactState(std::vector<ContactPoint>& points,
                          const std::vector<ContactPoint>& previous,
                          const std::vector<int>& parentFace, const mesh::SimplexMesh& mesh,
                          const Teuchos::Comm<int>& comm)
{
  // Every rank's previous points, as (parent face, index in its face, x, status, direction,
  // centroid, load-step history per weight, previous step's r_N and weight): the partition
  // changes between cycles, so a new face's parent may have lived on any rank. The list is
  // O(contact points), like the replicated mesh.
  const int d = mesh.dim();
  const int stride = 3 * d + 7;
  const int centroidAt = d + 5, historyAt = 2 * d + 5, normalAt = 3 * d + 5;
  std::vector<double> mine;
  mine.reserve(previous.size() * stride);
  for (const auto& q : previous) {
    mine.push_back(static_cast<double>(q.face));
    mine.push_back(static_cast<double>(q.index));
    mine.insert(mine.end(), q.x.begin(), q.x.begin() + d);
    mine.push_back(static_cast<double>(q.status));
    mine.push_back(q.direction[0]);
    mine.push_back(q.direction[1]);
    mine.insert(mine.end(), q.centroid.begin(), q.centroid.begin() + d);
    // (Points restored from a checkpoint carry no weight and no history.)
    for (int i = 0; i < d; ++i)
      mine.push_back(q.history[i] != 0.0 ? q.history[i] / q.weight : 0.0);
    mine.push_back(q.previousRN);
    mine.push_back(q.weight);
  }
  const auto all = core::gatherAllConcatenated(comm, mine);
  const std::size_t n = all.size() / stride;
  if (n == 0 || parentFace.empty()) return;  // no history (first cycle): every point starts free
  // The previous points grouped by face: (face, position in `all`), sorted.
  std::vector<std::pair<int, std::size_t>> byFace(n);
  for (std::size_t k = 0; k < n; ++k)
    byFace[k] = {static_cast<int>(all[k * stride]), k};
  std::sort(byFace.begin(), byFace.end());
  SC_THROW_IF(parentFace.size() != static_cast<std::size_t>(mesh.numFaces()), core::InternalError,
              "contact::transferContactState: " << parentFace.size()
                                                << " parent faces for a mesh of " << mesh.numFaces()
                                                << " faces");
  // Preference among previous points at the same distance (a new vertex halfway between two
  // control points, 3D): a contact state over free, stick over slip, then the lower index
  // within the parent face (fixed by the mesh, so the start does not depend on the rank count).
  // (Measured on the run_hertz3d_adaptive run, 2026-12-01: 21 Newton steps over cycles 0-6; with
  // free winning instead, 22.)
  auto preference = [](int status) {
    return status == static_cast<int>(PointStatus::Stick)  ? 2
           : status == static_cast<int>(PointStatus::Slip) ? 1
                                                           : 0;
  };
  for (auto& p : points) {
    const int parent = parentFace[p.face];
    if (parent < 0) continue;
    const auto range =
        std::equal_range(byFace.begin(), byFace.end(), std::make_pair(parent, std::size_t{0}),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
    if (range.first == range.second)
      continue;  // the parent face had no points (it was not a contact face): start free
    // Distances to the parent face's points; "equal" within 1e-8 of the largest (the face's
    // size squared), so that rounding in projected midpoints does not decide.
    double far = 0.0;
    std::vector<std::pair<double, std::size_t>> dist;
    for (auto it = range.first; it != range.second; ++it) {
      const double* x = &all[it->second * stride + 2];
      double d2 = 0.0;
      for (int i = 0; i < d; ++i)
        d2 += (p.x[i] - x[i]) * (p.x[i] - x[i]);
      dist.emplace_back(d2, it->second);
      far = std::max(far, d2);
    }
    double best = 1e300;
    for (const auto& dk : dist)
      best = std::min(best, dk.first);
    std::size_t chosen = dist.front().second;
    bool found = false;
    for (const auto& [d2, k] : dist) {
      if (d2 > best + 1e-8 * far) continue;
      if (!found) {
        chosen = k, found = true;
        continue;
      }
      const int s = static_cast<int>(all[k * stride + 2 + d]);
      const int sc = static_cast<int>(all[chosen * stride + 2 + d]);
      if (preference(s) > preference(sc) ||
          (preference(s) == preference(sc) && all[k * stride + 1] < all[chosen * stride + 1]))
        chosen = k;
    }
    p.status = static_cast<PointStatus>(static_cast<int>(all[chosen * stride + 2 + d]));
    p.direction = {all[chosen * stride + 3 + d], all[chosen * stride + 4 + d]};
    // The previous step's r_N (read only by a load step's first Newton update, on the mesh of
    // the step before: there it is the nearest point's value itself, the same point's); on a
    // refined face the nearest point's value per weight, times this point's weight.
    const double rN = all[chosen * stride + normalAt], w = all[chosen * stride + normalAt + 1];
    p.previousRN = (w == p.weight || rN == 0.0 || w <= 0.0) ? rN : rN / w * p.weight;
    // The load-step history: the parent face's per-weight values, placed at their weights'
    // centroids, fitted by an affine function of the position on the face (least squares) and
    // evaluated at this point's centroid, times its weight. Exact for a tangential trace that is
    // affine on the parent face, so the transfer costs O(h²) and repeated refinement of one
    // face reproduces the same affine function (docs/theory.md §"Load steps").
    std::vector<const double*> cq, vq;
    bool any = false;
    for (auto it = range.first; it != range.second; ++it) {
      cq.push_back(&all[it->second * stride + centroidAt]);
      vq.push_back(&all[it->second * stride + historyAt]);
      for (int i = 0; i < d; ++i)
        any = any || vq.back()[i] != 0.0;
    }
    p.history = {0.0, 0.0, 0.0};
    if (any) {
      // An unrefined face keeps its points: their values are taken as they are.
      const double* same = nullptr;
      for (std::size_t q = 0; q < cq.size() && !same; ++q) {
        double d2 = 0.0;
        for (int i = 0; i < d; ++i)
          d2 += (cq[q][i] - p.centroid[i]) * (cq[q][i] - p.centroid[i]);
        if (d2 <= 1e-20 * far) same = vq[q];
      }
      const auto v = same ? std::array<double, 3>{same[0], same[1], d == 3 ? same[2] : 0.0}
                          : disc::fitAffineOnFace(cq, vq, d, p.centroid.data());
      for (int i = 0; i < d; ++i)
        p.history[i] = p.weight * v[i];
    }
  }
}

}  // namespace sc::contact
