#include "sc/core/ProblemData.hpp"

#include <algorithm>
#include <climits>
#include <sstream>

#include "sc/core/Error.hpp"
#include "sc/core/ExactSolution.hpp"
#include "sc/core/Parameters.hpp"

namespace sc::core {
namespace {

std::vector<double> toVector(const Teuchos::Array<double>& a) { return {a.begin(), a.end()}; }

std::string joined(const std::vector<std::string>& names)
{
  std::ostringstream os;
  for (std::size_t i = 0; i < names.size(); ++i)
    os << (i ? ", " : "") << "'" << names[i] << "'";
  return os.str();
}

}  // namespace

// ----------------------------------------------------------------------------- Problem
Teuchos::RCP<const Teuchos::ParameterList> ProblemSettings::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Problem"));
    declareInt(*pl, "Dimension", 2, "Space dimension: 2 (plane strain) or 3.", 2, 3);
    declareString(*pl, "Name", "", "Free-text name of the study, copied to summary.json.");
    declareChoice(*pl, "Exact solution", "None", {"None", "Manufactured smooth", "Linear patch"},
                  "Known solution for verification: errors are reported in summary.json, and "
                  "boundary data of Type Displacement/Traction with 'Data' = 'Exact solution' and "
                  "the body force come from it (docs/verification.md).");
    declareReal(*pl, "Manufactured wavenumber", M_PI,
                "Wavenumber ω of 'Manufactured smooth' (sin ωx_i): π is one half wave across the "
                "unit square/cube; a smaller ω reaches the asymptotic rates on coarser meshes.",
                0.0, true);
    return pl;
  }();
  return valid;
}

ProblemSettings ProblemSettings::fromParameters(const Teuchos::ParameterList& pl)
{
  ProblemSettings s;
  s.dimension = pl.get<int>("Dimension");
  s.exactSolution = pl.get<std::string>("Exact solution");
  s.manufacturedWavenumber = pl.get<double>("Manufactured wavenumber");
  return s;
}

// ----------------------------------------------------------------------------- Material
Teuchos::RCP<const Teuchos::ParameterList> Material::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Material"));
    // With displacement loads stresses scale with E, and their squares leave double's normal
    // range near E = 1e±155 at hertz2d's strains of 1e-2: its stick/slip states change between
    // 1e155 and 1e160 (overflow) and between 1e-155 and 1e-165 (underflow; no convergence at
    // 1e-158 and 1e-160), and the compliance 1/E overflows below 1e-308 (MUMPS errors).
    // [1e-100, 1e100] is the range verified to give the same force/E and contact state (test
    // young_modulus_range; docs/reliability.md), with a wide margin for any unit system.
    declareReal(*pl, "Young modulus", 1.0,
                "Young's modulus E, in the deck's stress units, in [1e-100, 1e100]: the range "
                "verified to give results that scale exactly with E (outside it, squares of "
                "stresses over- or underflow).",
                1e-100, false, 1e100, false);
    declareReal(*pl, "Poisson ratio", 0.3,
                "Poisson's ratio ν in [0, 0.5]; 0.5 (incompressible) is valid: the method never "
                "forms λ (docs/theory.md §\"The problem\").",
                0.0, false, 0.5, false);
    declareChoice(*pl, "Plane", "Strain", {"Strain", "Stress"},
                  "2D only: plane strain (ε_zz = 0, a long body) or plane stress (σ_zz = 0, a thin "
                  "plate): the compliance is Aσ = ((1+ν)σ − ν tr(σ) I)/E in plane stress and "
                  "(1/2μ)(σ − ν tr(σ) I) in plane strain (docs/theory.md §\"Loads and "
                  "supports\"). 'Stress' in 3D is an input error.");
    return pl;
  }();
  return valid;
}

Material Material::fromParameters(const Teuchos::ParameterList& pl, int dimension)
{
  Material m;
  m.youngModulus = pl.get<double>("Young modulus");
  m.poissonRatio = pl.get<double>("Poisson ratio");
  m.planeStress = pl.get<std::string>("Plane") == "Stress";
  SC_THROW_IF(m.planeStress && dimension != 2, InputError,
              "'Material/Plane' = 'Stress' is a 2D model (a thin plate, σ_zz = 0), but "
              "Problem/Dimension is "
                  << dimension << ": remove the key or give 'Strain' (a 3D body has no plane "
                  << "model).");
  return m;
}

// ----------------------------------------------------------------------------- Boundary conditions
std::string toString(BoundaryType type)
{
  switch (type) {
  case BoundaryType::Displacement: return "Displacement";
  case BoundaryType::Traction: return "Traction";
  case BoundaryType::Pressure: return "Pressure";
  case BoundaryType::Symmetry: return "Symmetry";
  case BoundaryType::NormalDisplacement: return "Normal displacement";
  case BoundaryType::Components: return "Components";
  case BoundaryType::Contact: return "Contact";
  case BoundaryType::Free: return "Free";
  }
  return "?";
}

Teuchos::RCP<const Teuchos::ParameterList> BoundaryConditions::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Boundary Conditions"));
    Teuchos::ParameterList& t =
        pl->sublist(kTemplateSublist, false,
                    "One sublist per boundary part, named as the mesh names it (e.g. 'Top', "
                    "'Arc'). Parts not listed are traction-free.");
    declareChoice(t, "Type", "Free",
                  {"Displacement", "Traction", "Pressure", "Symmetry", "Normal displacement",
                   "Components", "Contact", "Free"},
                  "Displacement: u = u_D (natural in the stress formulation); Traction: σn = t "
                  "(essential); Pressure: σn = −p n, n the outward normal of the face (essential; "
                  "n varies along curved faces); Symmetry: u·n = 0 and zero tangential traction "
                  "(a symmetry plane, a roller or a sliding support); Normal displacement: u·n = g "
                  "(Value {g} or Expression {g}; g > 0 moves the part outwards) and zero "
                  "tangential traction. Symmetry and Normal displacement need a flat part (a "
                  "line in 2D, a plane in 3D) of any orientation, n its outward normal; a curved "
                  "part is an input error. Components: per global component i (x, y, z) either "
                  "u_i = g_i or (σn)_i = s_i, as 'Components' says, on a part of any shape "
                  "(curved too). "
                  "Contact: unilateral contact with the Contact/Obstacle; Free: σn = 0 "
                  "(docs/theory.md §\"Loads and supports\").");
    declareRealArray(t, "Value", Teuchos::Array<double>(),
                     "Constant data: u_D or t (one number per space dimension), p or g (one "
                     "number), g_i or s_i (Components: one number per space dimension, component "
                     "i's displacement or traction). Displacement, Traction, Pressure, Normal "
                     "displacement and Components take exactly one of Value, Expression and "
                     "Data = 'Exact solution' (the last for Displacement, Traction and "
                     "Components only).",
                     {0, 1, 2, 3});
    declareExpressionArray(t, "Expression",
                           "The data as formulas of x, y, z (one per component, like Value), "
                           "evaluated at the quadrature points, e.g. {0, -0.01*x} or {1e3*(1 - "
                           "y)}; no commas inside a formula (docs/user-guide.md \"Loads and "
                           "supports\").",
                           {0, 1, 2, 3});
    declareChoiceArray(t, "Components", {"Displacement", "Traction"},
                       "Type Components only: the condition of each global component, one entry "
                       "per space dimension in the order x, y(, z): Displacement (u_i = Value[i], "
                       "natural) or Traction ((σn)_i = Value[i], essential), e.g. {Displacement, "
                       "Traction}: u_x given, the traction's y component given (a roller on a "
                       "line x = const with {0, 0}); docs/theory.md §\"Loads and supports\".",
                       {0, 2, 3});
    declareRealArray(t, "Values per step", Teuchos::Array<double>(),
                     "Load steps (docs/theory.md §\"Load steps\"): the constant data of every "
                     "step, row after row (Value's components for step 1, then step 2, ...; as "
                     "many rows as 'Load steps/Times' has entries), instead of Value. E.g. "
                     "{0, -0.01, 0.004, -0.01}: press, then move sideways. Formulas may use t "
                     "instead ('Expression').",
                     {});
    declareChoice(t, "Data", "Value", {"Value", "Exact solution"},
                  "Where u_D or t comes from: 'Value' (the keys Value or Expression), or the "
                  "exact solution named by 'Problem/Exact solution' (manufactured scenes; "
                  "Displacement, Traction and Components: u_i or (σn)_i of the exact "
                  "solution).");
    return pl;
  }();
  return valid;
}

BoundaryConditions BoundaryConditions::fromParameters(const Teuchos::ParameterList& pl,
                                                      int dimension)
{
  BoundaryConditions bcs;
  for (auto it = pl.begin(); it != pl.end(); ++it) {
    const std::string& name = pl.name(it);
    const Teuchos::ParameterList& sub = pl.sublist(name);
    BoundaryCondition bc;
    bc.boundary = name;
    const std::string type = sub.get<std::string>("Type");
    bc.type = type == "Displacement"          ? BoundaryType::Displacement
              : type == "Traction"            ? BoundaryType::Traction
              : type == "Pressure"            ? BoundaryType::Pressure
              : type == "Symmetry"            ? BoundaryType::Symmetry
              : type == "Normal displacement" ? BoundaryType::NormalDisplacement
              : type == "Components"          ? BoundaryType::Components
              : type == "Contact"             ? BoundaryType::Contact
                                              : BoundaryType::Free;
    bc.value = toVector(sub.get<Teuchos::Array<double>>("Value"));
    bc.valuesPerStep = toVector(sub.get<Teuchos::Array<double>>("Values per step"));
    bc.fromExactSolution = sub.get<std::string>("Data") == "Exact solution";
    const std::string key = "Boundary Conditions/" + name;
    const auto& formulas = sub.get<Teuchos::Array<std::string>>("Expression");
    bc.expression = compileExpressions(formulas, key + "/Expression");
    SC_THROW_IF(!bc.valuesPerStep.empty() && (!bc.value.empty() || !bc.expression.empty()),
                InputError,
                "'" << key << "/Values per step' and '" << key << "/"
                    << (bc.value.empty() ? "Expression" : "Value")
                    << "' are both given; give one of them (Values per step: one row of "
                    << "constants per load step).");
    const bool hasValue = !bc.value.empty() || !bc.valuesPerStep.empty(),
               hasExpression = !bc.expression.empty();
    const auto components = trimmedEntries(sub.get<Teuchos::Array<std::string>>("Components"));
    SC_THROW_IF(bc.type != BoundaryType::Components && !components.empty(), InputError,
                "'" << key << "/Components' is given, but Type is '" << type
                    << "': the key is for Type Components only; remove it or set '" << key
                    << "/Type' = 'Components'.");
    if (bc.type == BoundaryType::Components) {
      SC_THROW_IF(components.size() != static_cast<std::size_t>(dimension), InputError,
                  "'" << key << "' (Type Components) needs '" << key << "/Components' with one "
                      << "entry per space dimension (Problem/Dimension is " << dimension
                      << "), each 'Displacement' or 'Traction', e.g. "
                      << (dimension == 2 ? "{Displacement, Traction}"
                                         : "{Displacement, Traction, Traction}")
                      << "; it has " << components.size() << ".");
      for (const auto& c : components)
        bc.components.push_back(c == "Displacement" ? ComponentCondition::Displacement
                                                    : ComponentCondition::Traction);
    }
    if (bc.type == BoundaryType::Displacement || bc.type == BoundaryType::Traction ||
        bc.type == BoundaryType::Pressure || bc.type == BoundaryType::NormalDisplacement ||
        bc.type == BoundaryType::Components) {
      // Pressure and Normal displacement take one scalar (p, g).
      const bool pressure =
          bc.type == BoundaryType::Pressure || bc.type == BoundaryType::NormalDisplacement;
      const char* scalar =
          bc.type == BoundaryType::Pressure ? "the pressure p" : "the normal displacement g";
      SC_THROW_IF(hasValue && hasExpression, InputError,
                  "'" << key << "/Value' and '" << key << "/Expression' are both given; give one "
                      << "of them (Value: constants, Expression: formulas of x, y, z).");
      SC_THROW_IF(bc.fromExactSolution && pressure, InputError,
                  "'" << key << "/Data' = 'Exact solution' is for Type Displacement, Traction or "
                      << "Components; "
                      << "Type " << type
                      << " takes 'Value' or 'Expression' (one number or formula).");
      SC_THROW_IF(bc.fromExactSolution && (hasValue || hasExpression), InputError,
                  "'" << key << "/Data' = 'Exact solution' takes the data from 'Problem/Exact "
                      << "solution', but '" << key << "/" << (hasValue ? "Value" : "Expression")
                      << "' is given too; remove one of them.");
      SC_THROW_IF(!bc.fromExactSolution && !hasValue && !hasExpression, InputError,
                  "'" << key << "' (Type " << type << ") has no data: give '" << key
                      << "/Value' (constants, e.g. "
                      << (pressure         ? "{1}"
                          : dimension == 2 ? "{0, 0}"
                                           : "{0, 0, 0}")
                      << ") or '" << key << "/Expression' (formulas of x, y, z"
                      << (pressure ? "" : ", one per component") << ").");
      const std::size_t expected = pressure ? 1 : static_cast<std::size_t>(dimension);
      const std::string what =
          pressure ? std::string("one value (") + scalar + ")" : "one value per dimension";
      SC_THROW_IF(!bc.valuesPerStep.empty() && bc.valuesPerStep.size() % expected != 0, InputError,
                  "'" << key << "/Values per step' has " << bc.valuesPerStep.size()
                      << " numbers, which is not a whole number of rows of " << expected
                      << (pressure ? std::string(" (") + scalar + " per step)"
                                   : std::string(" (one value per dimension per step)"))
                      << ".");
      SC_THROW_IF(!bc.value.empty() && bc.value.size() != expected, InputError,
                  "'" << key << "/Value' has " << bc.value.size() << " components, but "
                      << (pressure ? "Type " + type + " takes one"
                                   : "Problem/Dimension is " + std::to_string(dimension))
                      << ": give " << what << ".");
      SC_THROW_IF(hasExpression && bc.expression.size() != expected, InputError,
                  "'" << key << "/Expression' has " << bc.expression.size() << " formulas, but "
                      << (pressure ? "Type " + type + " takes one"
                                   : "Problem/Dimension is " + std::to_string(dimension))
                      << ": give " << (pressure ? "one formula" : "one formula per dimension")
                      << " (a formula cannot contain a comma: the array is split at commas).");
    } else {
      const char* given = !bc.value.empty()           ? "Value"
                          : !bc.valuesPerStep.empty() ? "Values per step"
                          : hasExpression             ? "Expression"
                                                      : "Data";
      SC_THROW_IF(hasValue || hasExpression || bc.fromExactSolution, InputError,
                  "'" << key << "/" << given << "' is given, but Type '" << type
                      << "' takes no data; remove it or use Type Displacement, Traction, "
                      << "Pressure, Normal displacement or Components.");
    }
    bcs.conditions.push_back(bc);
  }
  return bcs;
}

void BoundaryConditions::checkStepTables(int numSteps, int dimension) const
{
  for (const auto& c : conditions) {
    if (c.valuesPerStep.empty()) continue;
    const std::size_t row =
        c.type == BoundaryType::Pressure || c.type == BoundaryType::NormalDisplacement
            ? 1
            : static_cast<std::size_t>(dimension);
    SC_THROW_IF(c.valuesPerStep.size() != row * static_cast<std::size_t>(numSteps), InputError,
                "'Boundary Conditions/" << c.boundary << "/Values per step' has "
                                        << c.valuesPerStep.size() / row << " rows of " << row
                                        << ", but 'Load steps/Times' has " << numSteps
                                        << " entries: give one row per load step.");
  }
}

BoundaryConditions BoundaryConditions::atStep(int step, int dimension) const
{
  BoundaryConditions out = *this;
  for (auto& c : out.conditions) {
    if (c.valuesPerStep.empty()) continue;
    const std::size_t row =
        c.type == BoundaryType::Pressure || c.type == BoundaryType::NormalDisplacement
            ? 1
            : static_cast<std::size_t>(dimension);
    const auto first = c.valuesPerStep.begin() + static_cast<std::ptrdiff_t>(row * step);
    c.value.assign(first, first + static_cast<std::ptrdiff_t>(row));
  }
  return out;
}

bool BoundaryConditions::hasContact() const
{
  return std::any_of(conditions.begin(), conditions.end(),
                     [](const auto& c) { return c.type == BoundaryType::Contact; });
}

std::vector<std::string> BoundaryConditions::boundariesOfType(BoundaryType type) const
{
  std::vector<std::string> names;
  for (const auto& c : conditions)
    if (c.type == type) names.push_back(c.boundary);
  return names;
}

const BoundaryCondition* BoundaryConditions::find(const std::string& boundary) const
{
  for (const auto& c : conditions)
    if (c.boundary == boundary) return &c;
  return nullptr;
}

void BoundaryConditions::checkPressureDetermined(const std::vector<std::string>& meshBoundaries,
                                                 const Material& material) const
{
  // Plane stress (a 2D-only flag) keeps A I ≠ 0 at ν = 0.5.
  if (material.poissonRatio < 0.5 || material.planeStress) return;
  for (const auto& name : meshBoundaries) {
    const auto it = std::find_if(conditions.begin(), conditions.end(),
                                 [&](const BoundaryCondition& c) { return c.boundary == name; });
    // A Components part counts as a Displacement part, even with a traction component: that
    // component fixes c only where it is not tangential (c n_i ≠ 0), which is not checked here.
    if (it == conditions.end() || (it->type != BoundaryType::Displacement &&
                                   it->type != BoundaryType::Components && !it->inNormalFrame()))
      return;  // a traction (given, pressure, zero or contact) part fixes the mean pressure
  }
  SC_THROW_IF(
      true, InputError,
      "'Material/Poisson ratio' = 0.5 with a Displacement condition on every boundary part ("
          << joined(meshBoundaries)
          << (boundariesOfType(BoundaryType::Symmetry).empty() &&
                      boundariesOfType(BoundaryType::NormalDisplacement).empty()
                  ? ""
                  : "; Symmetry and Normal displacement parts count as such: c I n = c n is normal")
          << (boundariesOfType(BoundaryType::Components).empty()
                  ? ""
                  : "; Components parts count as such, also with a traction component")
          << "): the stress is then determined only up to a "
          << "constant pressure (the compliance of an incompressible material vanishes on "
          << "the identity) and the discrete problem is singular. Give at least one part "
          << "a Traction, Pressure, Free or Contact condition, or use a Poisson ratio below 0.5 "
          << "(e.g. 0.4999).");
}

void BoundaryConditions::checkBoundaryNames(const std::vector<std::string>& meshBoundaries,
                                            const std::string& meshDescription) const
{
  for (const auto& c : conditions) {
    SC_THROW_IF(
        std::find(meshBoundaries.begin(), meshBoundaries.end(), c.boundary) == meshBoundaries.end(),
        InputError,
        "'Boundary Conditions/" << c.boundary << "': the mesh (" << meshDescription
                                << ") has no boundary part named '" << c.boundary
                                << "'. Its boundary parts are: " << joined(meshBoundaries) << ".");
  }
}

namespace {
// Component i of constant (value, empty = zero) or formula data at x.
double component(const std::vector<double>& value, const std::vector<Expression>& expression, int i,
                 const double* x, int dim)
{
  if (!expression.empty()) return expression[i](x, dim);
  return value.empty() ? 0.0 : value[i];
}

bool constantZero(const std::vector<double>& value, const std::vector<Expression>& expression)
{
  return expression.empty() &&
         std::all_of(value.begin(), value.end(), [](double v) { return v == 0.0; });
}
}  // namespace

void BoundaryCondition::evaluate(const double* x, const double* n, int dim,
                                 const ExactSolution* exact, double* out) const
{
  std::fill(out, out + dim, 0.0);
  SC_THROW_IF(fromExactSolution && !exact, InputError,
              "'Boundary Conditions/" << boundary << "/Data' = 'Exact solution', but "
                                      << "'Problem/Exact solution' is 'None'.");
  switch (type) {
  case BoundaryType::Displacement:
    if (fromExactSolution)
      exact->displacement(x, out);
    else
      for (int i = 0; i < dim; ++i)
        out[i] = component(value, expression, i, x, dim);
    break;
  case BoundaryType::Traction:
    if (fromExactSolution)
      exact->traction(x, n, out);
    else
      for (int i = 0; i < dim; ++i)
        out[i] = component(value, expression, i, x, dim);
    break;
  case BoundaryType::Pressure: {
    const double p = component(value, expression, 0, x, dim);
    for (int i = 0; i < dim; ++i)
      out[i] = -p * n[i];
    break;
  }
  case BoundaryType::NormalDisplacement: {
    const double g = component(value, expression, 0, x, dim);
    for (int i = 0; i < dim; ++i)
      out[i] = g * n[i];
    break;
  }
  case BoundaryType::Components:
    if (fromExactSolution) {
      double u[3] = {0, 0, 0}, t[3] = {0, 0, 0};
      exact->displacement(x, u);
      exact->traction(x, n, t);
      for (int i = 0; i < dim; ++i)
        out[i] = displacementComponent(i) ? u[i] : t[i];
    } else {
      for (int i = 0; i < dim; ++i)
        out[i] = component(value, expression, i, x, dim);
    }
    break;
  default: break;
  }
}

bool BoundaryCondition::hasDisplacementComponent() const
{
  return type == BoundaryType::Components &&
         std::any_of(components.begin(), components.end(),
                     [](ComponentCondition c) { return c == ComponentCondition::Displacement; });
}

bool BoundaryCondition::isZero() const
{
  return !fromExactSolution && constantZero(value, expression);
}

// ----------------------------------------------------------------------------- Body force
Teuchos::RCP<const Teuchos::ParameterList> BodyForce::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Body Force"));
    declareRealArray(*pl, "Value", Teuchos::Array<double>(),
                     "Constant body force f (force per volume, one number per space dimension), "
                     "e.g. gravity {0, -9.81e3} (ρ g with ρ = 1000, g = 9.81 in y); empty: "
                     "f = 0. Give Value or Expression, not both.",
                     {0, 2, 3});
    declareExpressionArray(*pl, "Expression",
                           "The body force as formulas of x, y, z, one per space dimension, "
                           "e.g. {0, -9.81e3*(1 + 0.1*y)}; evaluated at the quadrature points.",
                           {0, 2, 3});
    declareRealArray(*pl, "Values per step", Teuchos::Array<double>(),
                     "Load steps (docs/theory.md §\"Load steps\"): the constant body force of "
                     "every step, row after row (one value per dimension per step), instead of "
                     "Value.",
                     {});
    return pl;
  }();
  return valid;
}

BodyForce BodyForce::fromParameters(const Teuchos::ParameterList& pl,
                                    const ProblemSettings& problem)
{
  BodyForce f;
  const int dim = problem.dimension;
  f.value = toVector(pl.get<Teuchos::Array<double>>("Value"));
  f.expression = compileExpressions(pl.get<Teuchos::Array<std::string>>("Expression"),
                                    "Body Force/Expression");
  f.valuesPerStep = toVector(pl.get<Teuchos::Array<double>>("Values per step"));
  SC_THROW_IF(!f.value.empty() && !f.expression.empty(), InputError,
              "'Body Force/Value' and 'Body Force/Expression' are both given; give one of them "
              "(Value: constants, Expression: formulas of x, y, z).");
  SC_THROW_IF(
      !f.valuesPerStep.empty() && (!f.value.empty() || !f.expression.empty()), InputError,
      "'Body Force/Values per step' and 'Body Force/"
          << (f.value.empty() ? "Expression" : "Value")
          << "' are both given; give one of them (Values per step: one row per load step).");
  SC_THROW_IF(f.valuesPerStep.size() % static_cast<std::size_t>(dim) != 0, InputError,
              "'Body Force/Values per step' has "
                  << f.valuesPerStep.size() << " numbers, which is not a whole number of rows of "
                  << dim << " (one value per dimension per step).");
  SC_THROW_IF(!f.valuesPerStep.empty() && problem.exactSolution != "None", InputError,
              "'Body Force/Values per step' is given, but 'Problem/Exact solution' = '"
                  << problem.exactSolution << "' defines the body force; remove one of them.");
  SC_THROW_IF(!f.value.empty() && static_cast<int>(f.value.size()) != dim, InputError,
              "'Body Force/Value' has " << f.value.size()
                                        << " components, but Problem/Dimension is " << dim
                                        << ": give one value per dimension.");
  SC_THROW_IF(!f.expression.empty() && static_cast<int>(f.expression.size()) != dim, InputError,
              "'Body Force/Expression' has "
                  << f.expression.size() << " formulas, but Problem/Dimension is " << dim
                  << ": give one formula per dimension (a formula cannot contain a comma: the "
                  << "array is split at commas).");
  SC_THROW_IF(
      (!f.value.empty() || !f.expression.empty()) && problem.exactSolution != "None", InputError,
      "'Body Force/" << (f.value.empty() ? "Expression" : "Value")
                     << "' is given, but 'Problem/Exact solution' = '" << problem.exactSolution
                     << "' defines the body force (f = −div σ of the exact solution); "
                     << "remove the Body Force or set 'Problem/Exact solution' = 'None'.");
  return f;
}

void BodyForce::checkStepTable(int numSteps, int dimension) const
{
  SC_THROW_IF(!valuesPerStep.empty() &&
                  valuesPerStep.size() != static_cast<std::size_t>(numSteps * dimension),
              InputError,
              "'Body Force/Values per step' has " << valuesPerStep.size() / dimension << " rows of "
                                                  << dimension << ", but 'Load steps/Times' has "
                                                  << numSteps
                                                  << " entries: give one row per load step.");
}

BodyForce BodyForce::atStep(int step, int dimension) const
{
  BodyForce out = *this;
  if (!valuesPerStep.empty()) {
    const auto first = valuesPerStep.begin() + static_cast<std::ptrdiff_t>(step * dimension);
    out.value.assign(first, first + dimension);
  }
  return out;
}

bool BodyForce::isZero() const { return constantZero(value, expression); }

void BodyForce::evaluate(const double* x, int dim, double* f) const
{
  for (int i = 0; i < dim; ++i)
    f[i] = component(value, expression, i, x, dim);
}

// ----------------------------------------------------------------------------- Method settings
Teuchos::RCP<const Teuchos::ParameterList> DiscretizationSettings::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Discretization"));
    declareInt(*pl, "Degree", 1,
               "Polynomial degree k of RT_k (stress rows) × DP_k (displacement) × CP_k "
               "(rotation), docs/theory.md §\"Mixed formulation\".",
               1, 4);
    return pl;
  }();
  return valid;
}

DiscretizationSettings DiscretizationSettings::fromParameters(const Teuchos::ParameterList& pl)
{
  DiscretizationSettings s;
  s.degree = pl.get<int>("Degree");
  return s;
}

}  // namespace sc::core
