#pragma once
// Marking strategies (docs/theory.md §"Adaptivity"): from the element indicators η_T² of every
// rank's owned elements, the global list of elements to bisect. The mesh is replicated, so every
// rank gets the same list: the indicators are summed into one array indexed by element (each
// element has exactly one owner, so the sum is exact) and every rank runs the same
// deterministic selection. Marking is by η_T², not by η_T²/|T| (docs/theory.md §"Estimator").
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>

namespace sc::adapt {

struct AdaptivitySettings;

class Marker {
public:
  virtual ~Marker() = default;
  virtual std::string name() const = 0;
  /// `indicators[i]` = η_T² of element `ownedElements[i]`; `numElements` = elements of the mesh.
  /// Returns the marked elements (sorted, the same on every rank).
  std::vector<int> mark(int numElements, const std::vector<int>& ownedElements,
                        const std::vector<double>& indicators,
                        const Teuchos::Comm<int>& comm) const;

protected:
  /// The selection from all elements' η_T² (identical input on every rank).
  virtual std::vector<int> select(const std::vector<double>& etaSquared) const = 0;
};

/// Dörfler (bulk) marking: the fewest elements, largest η_T² first, whose Σ η_T² ≥ θ Σ η²
/// (ties broken by element index).
class DorflerMarker : public Marker {
public:
  explicit DorflerMarker(double theta);
  std::string name() const override { return "Dorfler"; }

protected:
  std::vector<int> select(const std::vector<double>& etaSquared) const override;

private:
  double theta_;
};

/// Maximum strategy: η_T ≥ θ max η_T.
class MaximumMarker : public Marker {
public:
  explicit MaximumMarker(double theta);
  std::string name() const override { return "Maximum"; }

protected:
  std::vector<int> select(const std::vector<double>& etaSquared) const override;

private:
  double theta_;
};

/// Every element.
class UniformMarker : public Marker {
public:
  std::string name() const override { return "Uniform"; }

protected:
  std::vector<int> select(const std::vector<double>& etaSquared) const override;
};

/// The marker named by `Adaptivity/Marking` (an unknown name lists the valid ones).
std::unique_ptr<Marker> createMarker(const AdaptivitySettings& settings);

}  // namespace sc::adapt
