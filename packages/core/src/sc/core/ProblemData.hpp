#pragma once
// The data of a scene (docs/theory.md §"The problem", §9), separate from the kernels that use it:
// problem dimension, material, boundary conditions, and the discretisation degree.
// Each struct owns one sublist of the deck and describes it in getValidParameters();
// fromParameters() reads a validated list. The members carry no defaults of their own: the
// declarations are the only place a key gets its default value.
//
// The other settings live with their packages: "Contact" (with "Contact/Newton") in
// sc::contact::ContactSettings, "Linear Solver" in sc::solvers::LinearSolverFactory,
// "Estimator" in sc::estimator::EstimatorSettings, "Adaptivity" in sc::adapt::AdaptivitySettings.

#include <cmath>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include "sc/core/Expression.hpp"

namespace sc::core {

struct ProblemSettings {
  int dimension{};                  ///< 2 (plane strain) or 3
  std::string exactSolution;        ///< name for createExactSolution (ExactSolution.hpp)
  double manufacturedWavenumber{};  ///< ω of the smooth manufactured solution
  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();
  static ProblemSettings fromParameters(const Teuchos::ParameterList& problemList);
};

/// Isotropic linear elastic material given by E and ν. λ is never formed (docs/theory.md §"The
/// problem"), so ν = 0.5 (incompressible) is valid. In 2D the body is in plane strain (ε_zz = 0)
/// or, with `Plane` = `Stress`, in plane stress (σ_zz = 0, a thin plate); docs/theory.md §"Loads
/// and supports".
struct Material {
  double youngModulus{};
  double poissonRatio{};
  bool planeStress{};  ///< 2D only ("Material/Plane" = "Stress"); ignored in 3D

  double shearModulus() const { return youngModulus / (2.0 * (1.0 + poissonRatio)); }
  /// c_d in Aτ = (1/2μ)(τ − c_d tr(τ) I): ν / (1 + (d − 2)ν) for plane strain (d = 2) and 3D;
  /// ν / (1 + ν) for plane stress, where Aσ = ((1 + ν)σ − ν tr(σ) I)/E.
  double complianceCoefficient(int dim) const
  {
    if (dim == 2 && planeStress) return poissonRatio / (1.0 + poissonRatio);
    return poissonRatio / (1.0 + (dim - 2) * poissonRatio);
  }
  /// Aτ:τ = (1/2μ)(|τ|² − c_d (tr τ)²) for a d×d row-major τ: the compliance energy density, in
  /// which the estimator's efficiency and the Target error norm are measured (docs/theory.md).
  double complianceEnergyDensity(const double* tau, int dim) const
  {
    double tt = 0.0, trace = 0.0;
    for (int i = 0; i < dim * dim; ++i)
      tt += tau[i] * tau[i];
    for (int i = 0; i < dim; ++i)
      trace += tau[i * dim + i];
    return (tt - complianceCoefficient(dim) * trace * trace) / (2.0 * shearModulus());
  }
  /// Plane-strain modulus E* = E/(1 − ν²) used by the Hertz formulas (docs/theory.md §"Scenes").
  double planeStrainModulus() const { return youngModulus / (1.0 - poissonRatio * poissonRatio); }
  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();
  /// `dimension` = Problem/Dimension: Plane = Stress in 3D is an InputError.
  static Material fromParameters(const Teuchos::ParameterList& materialList, int dimension = 2);
};

enum class BoundaryType {
  Displacement,
  Traction,
  Pressure,
  Symmetry,
  NormalDisplacement,
  Components,
  Contact,
  Free
};
std::string toString(BoundaryType type);

/// The condition on one global component i of a Components part: u_i = g_i (natural in the
/// stress formulation) or (σn)_i = s_i (essential); docs/theory.md §"Loads and supports".
enum class ComponentCondition { Displacement, Traction };

class ExactSolution;

/// One boundary part's condition (docs/theory.md §"The problem" and §"Loads and supports"). Its
/// data is `value` (constants), `expression` (formulas of x, y, z) or the exact solution, one
/// of the three: u_D (Displacement, d components), t (Traction, d) or the pressure p (Pressure,
/// one) or g (Normal displacement: u·n = g and zero tangential traction, one), or per global
/// component g_i or s_i (Components, d, with `components` saying which). Symmetry (u·n = 0,
/// zero tangential traction), Contact and Free take no data.
struct BoundaryCondition {
  std::string boundary;  ///< name of the boundary part (mesh physical name)
  BoundaryType type = BoundaryType::Free;
  std::vector<double> value;           ///< constant data; empty (and no expression) means zero
  bool fromExactSolution = false;      ///< u_D or t from Problem/Exact solution instead of value
  std::vector<Expression> expression;  ///< formulas instead of value (one per component)
  /// "Values per step": the constant data of every load step, row after row (docs/theory.md
  /// §"Load steps"); `value` is set from row n for step n (BoundaryConditions::atStep).
  std::vector<double> valuesPerStep;
  /// Components: the condition of each global component (d entries: x, y(, z)).
  std::vector<ComponentCondition> components;

  /// The data at the boundary point x with the outward unit normal n (d components): u_D
  /// (Displacement), t (Traction: the value, the formulas or σ(x)n of the exact solution),
  /// −p(x) n (Pressure), g(x) n (Normal displacement), or per component g_i or s_i
  /// (Components: u_i or (σ(x)n)_i of the exact solution); zero for the other types. `exact` is
  /// needed when fromExactSolution.
  void evaluate(const double* x, const double* n, int dim, const ExactSolution* exact,
                double* out) const;
  /// True when the data is the constant zero (no formula, no exact solution).
  bool isZero() const;
  /// Symmetry or Normal displacement: a condition in the part's normal–tangential frame.
  bool inNormalFrame() const
  {
    return type == BoundaryType::Symmetry || type == BoundaryType::NormalDisplacement;
  }
  /// Components with u_i given (the component is natural in the stress formulation).
  bool displacementComponent(int i) const
  {
    return type == BoundaryType::Components &&
           components.at(static_cast<std::size_t>(i)) == ComponentCondition::Displacement;
  }
  /// Components with at least one displacement component (it holds rigid motions along e_i).
  bool hasDisplacementComponent() const;
};
/// "Boundary Conditions/<boundary name>/{Type, Value, Expression, Data}". Boundary parts not named
/// in the deck are traction-free.
struct BoundaryConditions {
  std::vector<BoundaryCondition> conditions;

  bool hasContact() const;
  std::vector<std::string> boundariesOfType(BoundaryType type) const;
  const BoundaryCondition* find(const std::string& boundary) const;
  /// Checks every named boundary exists in `meshBoundaries`; the error lists the valid names.
  /// At ν = 0.5 the compliance annihilates the identity (A I = 0; not in plane stress): with a
  /// Displacement or Symmetry condition on every boundary part no traction fixes the mean
  /// pressure (c I n = c n is normal, which a Symmetry part allows), σ_h + c I solves the
  /// discrete problem for every c and the matrix is singular (a direct solver may still return a
  /// solution, with an arbitrary pressure). Throws InputError naming the keys in that case.
  void checkPressureDetermined(const std::vector<std::string>& meshBoundaries,
                               const Material& material) const;
  void checkBoundaryNames(const std::vector<std::string>& meshBoundaries,
                          const std::string& meshDescription) const;

  /// Load steps: every "Values per step" table has `numSteps` rows (InputError naming the key
  /// otherwise).
  void checkStepTables(int numSteps, int dimension) const;
  /// The conditions of load step `step` (0-based): each table's row as the part's Value.
  BoundaryConditions atStep(int step, int dimension) const;

  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();
  static BoundaryConditions fromParameters(const Teuchos::ParameterList& bcList, int dimension);
};

/// "Body Force/{Value, Expression}": the body force f in div σ + f = 0 (force per volume; e.g.
/// gravity {0, −ρg}), constant or by formulas of x, y, z; zero when neither is given. With
/// Problem/Exact solution f comes from the exact solution and this list must stay empty.
struct BodyForce {
  std::vector<double> value;           ///< d constants, or empty
  std::vector<Expression> expression;  ///< d formulas, or empty
  std::vector<double> valuesPerStep;   ///< "Values per step": d values per load step

  /// Load steps: the table has `numSteps` rows of d values (InputError otherwise).
  void checkStepTable(int numSteps, int dimension) const;
  /// The body force of load step `step` (0-based): the table's row as Value.
  BodyForce atStep(int step, int dimension) const;

  bool isZero() const;
  /// f(x), d components.
  void evaluate(const double* x, int dim, double* f) const;

  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();
  /// `problem` gives the dimension and the exact solution (a body force beside one is an
  /// InputError: the exact solution defines f = −div σ).
  static BodyForce fromParameters(const Teuchos::ParameterList& bodyForceList,
                                  const ProblemSettings& problem);
};

struct DiscretizationSettings {
  int degree{};  ///< k of RT_k × DP_k × CP_k (docs/theory.md §"Mixed formulation")
  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();
  static DiscretizationSettings fromParameters(const Teuchos::ParameterList& list);
};

}  // namespace sc::core
