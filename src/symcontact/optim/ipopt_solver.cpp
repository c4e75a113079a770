#include "symcontact/optim/ipopt_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wpedantic"
#include <coin/IpIpoptApplication.hpp>
#include <coin/IpSolveStatistics.hpp>
#include <coin/IpTNLP.hpp>
#pragma GCC diagnostic pop

#include "symcontact/core/error.hpp"
#include "symcontact/core/interrupt.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/optim/ordering_seed.hpp"

namespace symcontact {
namespace {

// Ipopt::Index (int) is not symcontact::Index (int64): spell the IPOPT types out.
using IpIndex = Ipopt::Index;
using IpNumber = Ipopt::Number;

/// IPOPT's default for nlp_upper_bound_inf: any bound ≥ 1e19 means "no bound".
constexpr double kIpoptInfinity = 1e19;

std::string status_name(int status) {
  switch (static_cast<Ipopt::ApplicationReturnStatus>(status)) {
    case Ipopt::Solve_Succeeded: return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level: return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected: return "Infeasible_Problem_Detected";
    case Ipopt::Search_Direction_Becomes_Too_Small: return "Search_Direction_Becomes_Too_Small";
    case Ipopt::Diverging_Iterates: return "Diverging_Iterates";
    case Ipopt::User_Requested_Stop: return "User_Requested_Stop";
    case Ipopt::Feasible_Point_Found: return "Feasible_Point_Found";
    case Ipopt::Maximum_Iterations_Exceeded: return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed: return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation: return "Error_In_Step_Computation";
    case Ipopt::Maximum_CpuTime_Exceeded: return "Maximum_CpuTime_Exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom: return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::Invalid_Problem_Definition: return "Invalid_Problem_Definition";
    case Ipopt::Invalid_Option: return "Invalid_Option";
    case Ipopt::Invalid_Number_Detected: return "Invalid_Number_Detected";
    case Ipopt::Unrecoverable_Exception: return "Unrecoverable_Exception";
    case Ipopt::NonIpopt_Exception_Thrown: return "NonIpopt_Exception_Thrown";
    case Ipopt::Insufficient_Memory: return "Insufficient_Memory";
    case Ipopt::Internal_Error: return "Internal_Error";
  }
  return "Unknown_Status_" + std::to_string(status);
}

/// Adds the wall time of its scope to a counter (callback timing).
class CallbackTimer {
 public:
  explicit CallbackTimer(double& total) : total_(total), start_(wall_seconds()) {}
  ~CallbackTimer() { total_ += wall_seconds() - start_; }
  CallbackTimer(const CallbackTimer&) = delete;
  CallbackTimer& operator=(const CallbackTimer&) = delete;

 private:
  double& total_;
  double start_;
};

/// What the adapter needs besides the problem; computed in solve_with_ipopt from x0.
struct AdapterSetup {
  VectorXd x0;
  const VectorXd* multipliers0 = nullptr;  ///< μ ≥ 0 convention; used when warm starting
  const VectorXd* bound_multipliers0 = nullptr;  ///< z ≥ 0 of the lower bounds; used when warm starting
  SparseMatrix hessian0;                   ///< lower triangle at x0, compressed: fixes the pattern
  ProblemScales scales;                    ///< g_ref and ℓ (see the header)
};

/// The TNLP: translation only. IPOPT sees n free variables and m constraints g(x) = A x + b ∈ [0, ∞).
class ContactTNLP final : public Ipopt::TNLP {
 public:
  ContactTNLP(ConstrainedProblem& problem, AdapterSetup setup, IpoptResult& result)
      : problem_(problem),
        A_(problem.constraint_matrix()),
        b_(problem.constraint_offset()),
        setup_(std::move(setup)),
        result_(result) {
    // Jacobian triplets in the storage order of A (values are copied in the same order).
    jac_rows_.reserve(static_cast<size_t>(A_.nonZeros()));
    for (int j = 0; j < A_.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A_, j); it; ++it) {
        jac_rows_.push_back(static_cast<IpIndex>(it.row()));
        jac_cols_.push_back(static_cast<IpIndex>(it.col()));
        jac_values_.push_back(it.value());
      }
    // Hessian pattern at x0 (compressed, lower triangle). Slot k of IPOPT's values array is entry k
    // of this storage; hessian_values() maps later evaluations onto it.
    const SparseMatrix& H = setup_.hessian0;
    hess_outer_.assign(H.outerIndexPtr(), H.outerIndexPtr() + H.outerSize() + 1);
    hess_inner_.assign(H.innerIndexPtr(), H.innerIndexPtr() + H.nonZeros());
    x_.resize(problem.num_variables());
  }

  bool get_nlp_info(IpIndex& n, IpIndex& m, IpIndex& nnz_jac_g, IpIndex& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = static_cast<IpIndex>(x_.size());
    m = static_cast<IpIndex>(A_.rows());
    nnz_jac_g = static_cast<IpIndex>(jac_rows_.size());
    nnz_h_lag = static_cast<IpIndex>(hess_inner_.size());
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(IpIndex n, IpNumber* x_l, IpNumber* x_u, IpIndex m, IpNumber* g_l,
                       IpNumber* g_u) override {
    std::fill(x_l, x_l + n, -kIpoptInfinity);
    if (const VectorXd* lower = problem_.lower_bounds()) std::copy(lower->data(), lower->data() + n, x_l);
    std::fill(x_u, x_u + n, kIpoptInfinity);
    std::fill(g_l, g_l + m, 0.0);
    std::fill(g_u, g_u + m, kIpoptInfinity);
    std::fill(g_u, g_u + std::min<IpIndex>(m, static_cast<IpIndex>(problem_.num_equalities())), 0.0);
    return true;
  }

  bool get_scaling_parameters(IpNumber& obj_scaling, bool& use_x_scaling, IpIndex n,
                              IpNumber* x_scaling, bool& use_g_scaling, IpIndex m,
                              IpNumber* g_scaling) override {
    // x̃ = x / ℓ, f̃ = f / (g_ref ℓ), g̃_i = g_i / (ℓ max_j |A_ij|): every scaled quantity is dimensionless.
    const double ell = setup_.scales.length;
    obj_scaling = setup_.scales.objective_scaling();
    use_x_scaling = true;
    std::fill(x_scaling, x_scaling + n, 1.0 / ell);
    use_g_scaling = true;
    std::fill(g_scaling, g_scaling + m, 0.0);
    for (size_t k = 0; k < jac_rows_.size(); ++k) {
      double& s = g_scaling[jac_rows_[k]];
      s = std::max(s, std::abs(jac_values_[k]));
    }
    for (IpIndex i = 0; i < m; ++i) g_scaling[i] = g_scaling[i] > 0.0 ? 1.0 / (ell * g_scaling[i]) : 1.0 / ell;
    return true;
  }

  bool get_starting_point(IpIndex n, bool init_x, IpNumber* x, bool init_z, IpNumber* z_L,
                          IpNumber* z_U, IpIndex m, bool init_lambda, IpNumber* lambda) override {
    if (init_x) std::copy(setup_.x0.data(), setup_.x0.data() + n, x);
    if (init_z) {  // only a warm start asks for them: the bounds' multipliers it was given, else zero
      std::fill(z_L, z_L + n, 0.0);
      std::fill(z_U, z_U + n, 0.0);
      if (setup_.bound_multipliers0) std::copy(setup_.bound_multipliers0->data(), setup_.bound_multipliers0->data() + n, z_L);
    }
    if (init_lambda) {
      // IPOPT's λ = −μ. Without multipliers (warm_start_init_point set by the user alone): zero.
      for (IpIndex i = 0; i < m; ++i) lambda[i] = setup_.multipliers0 ? -(*setup_.multipliers0)[i] : 0.0;
    }
    return true;
  }

  bool eval_f(IpIndex n, const IpNumber* x, bool /*new_x*/, IpNumber& obj_value) override {
    CallbackTimer timer(result_.seconds_in_callbacks);
    try {
      obj_value = problem_.objective(load_x(n, x));
    } catch (const EvaluationError&) {
      return false;
    }
    return true;
  }

  bool eval_grad_f(IpIndex n, const IpNumber* x, bool /*new_x*/, IpNumber* grad_f) override {
    CallbackTimer timer(result_.seconds_in_callbacks);
    try {
      problem_.gradient(load_x(n, x), grad_);
    } catch (const EvaluationError&) {
      return false;
    }
    SYMCONTACT_ASSERT(grad_.size() == n);
    std::copy(grad_.data(), grad_.data() + n, grad_f);
    return true;
  }

  bool eval_g(IpIndex n, const IpNumber* x, bool /*new_x*/, IpIndex m, IpNumber* g) override {
    CallbackTimer timer(result_.seconds_in_callbacks);
    Eigen::Map<VectorXd>(g, m).noalias() = A_ * load_x(n, x);
    Eigen::Map<VectorXd>(g, m) += b_;
    return true;
  }

  bool eval_jac_g(IpIndex /*n*/, const IpNumber* /*x*/, bool /*new_x*/, IpIndex /*m*/, IpIndex nele_jac,
                  IpIndex* iRow, IpIndex* jCol, IpNumber* values) override {
    SYMCONTACT_ASSERT(static_cast<size_t>(nele_jac) == jac_rows_.size());
    if (values == nullptr) {
      std::copy(jac_rows_.begin(), jac_rows_.end(), iRow);
      std::copy(jac_cols_.begin(), jac_cols_.end(), jCol);
    } else {
      std::copy(jac_values_.begin(), jac_values_.begin() + nele_jac, values);
    }
    return true;
  }

  bool eval_h(IpIndex n, const IpNumber* x, bool /*new_x*/, IpNumber obj_factor, IpIndex /*m*/,
              const IpNumber* /*lambda*/, bool /*new_lambda*/, IpIndex nele_hess, IpIndex* iRow,
              IpIndex* jCol, IpNumber* values) override {
    SYMCONTACT_ASSERT(static_cast<size_t>(nele_hess) == hess_inner_.size());
    if (values == nullptr) {
      // IPOPT wants the lower triangle (row ≥ column) of the symmetric Hessian of the Lagrangian.
      for (size_t j = 0; j + 1 < hess_outer_.size(); ++j)
        for (int k = hess_outer_[j]; k < hess_outer_[j + 1]; ++k) {
          const IpIndex r = hess_inner_[k], c = static_cast<IpIndex>(j);
          iRow[k] = std::max(r, c);
          jCol[k] = std::min(r, c);
        }
      return true;
    }
    // ∇²L = obj_factor ∇²f + Σ λ_i ∇²g_i = obj_factor ∇²f (linear constraints).
    std::fill(values, values + nele_hess, 0.0);
    if (obj_factor == 0.0) return true;
    CallbackTimer timer(result_.seconds_in_callbacks);
    try {
      problem_.hessian_lower(load_x(n, x), hess_);
    } catch (const EvaluationError&) {
      return false;
    }
    hess_.makeCompressed();
    scatter_hessian(obj_factor, values);
    return true;
  }

  /// Called by IPOPT after each iteration: false stops it (User_Requested_Stop) once SIGINT or SIGTERM
  /// has arrived (interrupt.hpp).
  bool intermediate_callback(Ipopt::AlgorithmMode /*mode*/, IpIndex /*iter*/, IpNumber /*obj_value*/,
                             IpNumber /*inf_pr*/, IpNumber /*inf_du*/, IpNumber /*mu*/, IpNumber /*d_norm*/,
                             IpNumber /*regularization_size*/, IpNumber /*alpha_du*/, IpNumber /*alpha_pr*/,
                             IpIndex /*ls_trials*/, const Ipopt::IpoptData* /*ip_data*/,
                             Ipopt::IpoptCalculatedQuantities* /*ip_cq*/) override {
    return !interrupt_requested();
  }

  void finalize_solution(Ipopt::SolverReturn /*status*/, IpIndex n, const IpNumber* x,
                         const IpNumber* z_L, const IpNumber* /*z_U*/, IpIndex m, const IpNumber* g,
                         const IpNumber* lambda, IpNumber obj_value, const Ipopt::IpoptData* /*ip_data*/,
                         Ipopt::IpoptCalculatedQuantities* /*ip_cq*/) override {
    result_.x = Eigen::Map<const VectorXd>(x, n);
    // IPOPT's Lagrangian is f + λᵀg, so λ ≤ 0 at a KKT point of g ≥ 0; we report μ = −λ ≥ 0.
    result_.multipliers = -Eigen::Map<const VectorXd>(lambda, m);
    result_.constraint_values = Eigen::Map<const VectorXd>(g, m);
    result_.bound_multipliers = problem_.lower_bounds() ? VectorXd(Eigen::Map<const VectorXd>(z_L, n)) : VectorXd::Zero(n);
    result_.objective = obj_value;
    finalized_ = true;
  }

  bool finalized() const { return finalized_; }

 private:
  const VectorXd& load_x(IpIndex n, const IpNumber* x) {
    x_ = Eigen::Map<const VectorXd>(x, n);
    return x_;
  }

  /// values[k] = obj_factor · H(slot k). Fast path: the evaluation has exactly the pattern of x0.
  /// Otherwise (entries in another order, or explicit zeros dropped) each entry is located in the x0
  /// pattern by binary search; a nonzero outside that pattern violates the ConstrainedProblem
  /// contract and throws std::logic_error.
  void scatter_hessian(double obj_factor, IpNumber* values) const {
    const size_t nnz = hess_inner_.size();
    const bool same_pattern =
        static_cast<size_t>(hess_.nonZeros()) == nnz &&
        static_cast<size_t>(hess_.outerSize()) + 1 == hess_outer_.size() &&
        std::equal(hess_outer_.begin(), hess_outer_.end(), hess_.outerIndexPtr()) &&
        std::equal(hess_inner_.begin(), hess_inner_.end(), hess_.innerIndexPtr());
    if (same_pattern) {
      const double* v = hess_.valuePtr();
      for (size_t k = 0; k < nnz; ++k) values[k] = obj_factor * v[k];
      return;
    }
    if (static_cast<size_t>(hess_.outerSize()) + 1 != hess_outer_.size())
      throw std::logic_error("solve_with_ipopt: the Hessian changed size during the solve");
    for (int j = 0; j < hess_.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(hess_, j); it; ++it) {
        const auto first = hess_inner_.begin() + hess_outer_[j];
        const auto last = hess_inner_.begin() + hess_outer_[j + 1];
        const auto pos = std::lower_bound(first, last, static_cast<int>(it.row()));
        if (pos != last && *pos == it.row()) {
          values[pos - hess_inner_.begin()] += obj_factor * it.value();
        } else if (it.value() != 0.0) {
          std::ostringstream msg;
          msg << "solve_with_ipopt: the Hessian has a nonzero at (" << it.row() << ", " << j
              << ") outside its sparsity pattern at x0; ConstrainedProblem::hessian_lower must keep "
                 "one pattern during a solve (store explicit zeros)";
          throw std::logic_error(msg.str());
        }
      }
  }

  ConstrainedProblem& problem_;
  const SparseMatrix& A_;
  const VectorXd& b_;
  AdapterSetup setup_;
  IpoptResult& result_;
  std::vector<IpIndex> jac_rows_, jac_cols_;
  std::vector<double> jac_values_;
  std::vector<int> hess_outer_, hess_inner_;
  VectorXd x_, grad_;
  SparseMatrix hess_;
  bool finalized_ = false;
};

// ---- options ----

const char* type_name(Ipopt::RegisteredOptionType t) {
  switch (t) {
    case Ipopt::OT_Number: return "a number";
    case Ipopt::OT_Integer: return "an integer";
    case Ipopt::OT_String: return "a string";
    case Ipopt::OT_Unknown: break;
  }
  return "of unknown type";
}

[[noreturn]] void throw_option_error(const std::string& name, const std::string& value,
                                     const std::string& why) {
  throw IpoptOptionError(name, "IPOPT option '" + name + "' = '" + value + "': " + why);
}

std::string to_text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

/// "expected a number > 0", "expected an integer in [0, 12]": the registered range of a numeric or
/// integer option, for messages.
std::string expected_range(const Ipopt::RegisteredOption& option) {
  const bool integer = option.Type() == Ipopt::OT_Integer;
  auto bound = [&](bool lower) {
    return integer ? std::to_string(lower ? option.LowerInteger() : option.UpperInteger())
                   : to_text(lower ? option.LowerNumber() : option.UpperNumber());
  };
  std::string s = integer ? "expected an integer" : "expected a number";
  // IPOPT initialises a bound's strictness only for a number option that has that bound (an integer
  // option's, and an absent bound's, are left uninitialised): read it only then.
  const bool lower_strict = !integer && option.HasLower() && option.LowerStrict();
  const bool upper_strict = !integer && option.HasUpper() && option.UpperStrict();
  if (option.HasLower() && option.HasUpper()) {
    s += std::string(" in ") + (lower_strict ? "(" : "[") + bound(true) + ", " + bound(false) + (upper_strict ? ")" : "]");
  } else if (option.HasLower()) {
    s += std::string(lower_strict ? " > " : " >= ") + bound(true);
  } else if (option.HasUpper()) {
    s += std::string(upper_strict ? " < " : " <= ") + bound(false);
  }
  return s;
}

/// A user option, given as a string, a number or an integer. Strings are converted to the option's
/// registered type (as IPOPT does for its options file); integers are accepted for numbers, and
/// integral numbers for integers. Anything else is an std::invalid_argument naming the option.
struct UserValue {
  enum Kind { kString, kNumber, kInteger } kind;
  std::string text;
  double number = 0.0;
  int integer = 0;
};

void set_user_option(Ipopt::IpoptApplication& app, const std::string& name, const UserValue& value) {
  const std::string shown = value.kind == UserValue::kString    ? value.text
                            : value.kind == UserValue::kInteger ? std::to_string(value.integer)
                                                                : to_text(value.number);
  const Ipopt::SmartPtr<const Ipopt::RegisteredOption> option = app.RegOptions()->GetOption(name);
  if (Ipopt::IsNull(option)) throw_option_error(name, shown, "no such IPOPT option (IPOPT 3.11)");
  const Ipopt::RegisteredOptionType type = option->Type();
  bool ok = false;
  if (type == Ipopt::OT_String) {
    if (value.kind != UserValue::kString)
      throw_option_error(name, shown, "expected a string, got a number");
    if (!option->IsValidStringSetting(value.text)) {
      std::string valid;
      for (const auto& s : option->GetValidStrings()) valid += (valid.empty() ? "" : ", ") + s.value_;
      throw_option_error(name, shown, "not a valid setting (valid: " + valid + ")");
    }
    ok = app.Options()->SetStringValue(name, value.text);
  } else if (type == Ipopt::OT_Number) {
    double v = value.number;
    if (value.kind == UserValue::kInteger) v = value.integer;
    if (value.kind == UserValue::kString) {
      char* end = nullptr;
      v = std::strtod(value.text.c_str(), &end);
      if (value.text.empty() || *end != '\0') throw_option_error(name, shown, "expected a number");
    }
    if (!option->IsValidNumberSetting(v)) throw_option_error(name, shown, "out of range, " + expected_range(*option));
    ok = app.Options()->SetNumericValue(name, v);
  } else if (type == Ipopt::OT_Integer) {
    long v = value.integer;
    if (value.kind == UserValue::kNumber) {
      if (value.number != std::floor(value.number) || std::abs(value.number) > 2e9)
        throw_option_error(name, shown, "expected an integer");
      v = static_cast<long>(value.number);
    }
    if (value.kind == UserValue::kString) {
      char* end = nullptr;
      v = std::strtol(value.text.c_str(), &end, 10);
      if (value.text.empty() || *end != '\0') throw_option_error(name, shown, "expected an integer");
    }
    if (!option->IsValidIntegerSetting(static_cast<IpIndex>(v)))
      throw_option_error(name, shown, "out of range, " + expected_range(*option));
    ok = app.Options()->SetIntegerValue(name, static_cast<IpIndex>(v));
  } else {
    throw_option_error(name, shown, std::string("option is ") + type_name(type));
  }
  if (!ok) throw_option_error(name, shown, "rejected by IPOPT");
}

void set_user_options(Ipopt::IpoptApplication& app, const IpoptOptions& options) {
  for (const auto& [name, v] : options.string_options)
    set_user_option(app, name, UserValue{UserValue::kString, v, 0.0, 0});
  for (const auto& [name, v] : options.numeric_options)
    set_user_option(app, name, UserValue{UserValue::kNumber, {}, v, 0});
  for (const auto& [name, v] : options.integer_options)
    set_user_option(app, name, UserValue{UserValue::kInteger, {}, 0.0, v});
}

void set_default(Ipopt::IpoptApplication& app, const std::string& name, const std::string& v) {
  if (!app.Options()->SetStringValue(name, v))
    throw std::logic_error("solve_with_ipopt: IPOPT rejected the default option " + name + " = " + v);
}
void set_default(Ipopt::IpoptApplication& app, const std::string& name, double v) {
  if (!app.Options()->SetNumericValue(name, v))
    throw std::logic_error("solve_with_ipopt: IPOPT rejected the default option " + name + " = " +
                           to_text(v));
}
void set_default(Ipopt::IpoptApplication& app, const std::string& name, int v) {
  if (!app.Options()->SetIntegerValue(name, v))
    throw std::logic_error("solve_with_ipopt: IPOPT rejected the default option " + name + " = " +
                           std::to_string(v));
}

/// min over the non-empty rows i of max_j |A_ij| (1 without any).
double smallest_row_scale(const SparseMatrix& A) {
  VectorXd row_max = VectorXd::Zero(A.rows());
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      row_max[it.row()] = std::max(row_max[it.row()], std::abs(it.value()));
  double smallest = std::numeric_limits<double>::infinity();
  for (Index i = 0; i < row_max.size(); ++i)
    if (row_max[i] > 0.0) smallest = std::min(smallest, row_max[i]);
  return std::isfinite(smallest) ? smallest : 1.0;
}


/// symcontact's IPOPT options (before the user's): output, linear solver, tolerances on the scaled problem and the
/// absolute checks rescaled to mean the same (see the header), exact constraints, and a warm start's small pushes.
void set_defaults(Ipopt::IpoptApplication& app, const IpoptOptions& options, const ConstrainedProblem& problem,
                  const ProblemScales& scales, bool warm) {
  const SparseMatrix& A = problem.constraint_matrix();
  const double g_ref = scales.force, e_ref = scales.force * scales.length;
  set_default(app, "sb", std::string("yes"));  // no banner
  set_default(app, "print_level", std::max(0, std::min(options.print_level, 12)));
  if (!options.output_file.empty()) {
    set_default(app, "output_file", options.output_file);
    set_default(app, "file_print_level", std::min(12, std::max(5, options.print_level)));
  }
  set_default(app, "linear_solver", std::string("mumps"));
  if (problem.hessian_is_dense()) {
    // A full Hessian block (the condensed problem, the dual on symmetric pairs): no fill to reduce and nothing
    // for MUMPS's maximum-transversal permutation and scaling to find, yet its analysis runs them at every
    // IPOPT call on the (n + m)-row KKT pattern. They are turned off and the ordering is plain AMD: a cheaper
    // analysis, with the same iterates (on the inclined interface with Coulomb friction: the same IPOPT
    // iterations and |R_x/R_y| to 9 digits).
    set_default(app, "mumps_permuting_scaling", 0);
    set_default(app, "mumps_scaling", 0);
    set_default(app, "mumps_pivot_order", 0);
  }
  set_default(app, "mu_strategy", std::string("adaptive"));
  set_default(app, "max_iter", options.max_iterations);
  set_default(app, "tol", options.tolerance);
  // Absolute checks on the unscaled problem, rescaled to mean what IPOPT's defaults (1, 1e-4, 1e10,
  // 1e-2) mean on the dimensionless one: the unscaled dual infeasibility is a force (× g_ref), the
  // unscaled complementarity g_i λ_i an energy (× g_ref ℓ).
  set_default(app, "dual_inf_tol", 1.0 * g_ref);
  set_default(app, "compl_inf_tol", 1e-4 * e_ref);
  set_default(app, "acceptable_dual_inf_tol", 1e10 * g_ref);
  set_default(app, "acceptable_compl_inf_tol", 1e-2 * e_ref);
  // The unscaled constraint violation: row i in units of ℓ max_j |A_ij|; the smallest row's unit makes every
  // row at least as strict as IPOPT's 1e-4 (1e-2 acceptable) on the dimensionless problem.
  const double c_ref = scales.length * smallest_row_scale(A);
  set_default(app, "constr_viol_tol", 1e-4 * c_ref);
  set_default(app, "acceptable_constr_viol_tol", 1e-2 * c_ref);
  // Acceptable termination: after 10 iterations within a = max(tol, min(1e-6, 1e4·tol)) whose scaled objective
  // also changes by less than a² (of max(1, |f̃|): IPOPT's rule). Near a minimiser the objective lies above its
  // minimum by about ½ δᵀH⁻¹δ for a dual infeasibility δ, i.e. δ² in the scaled problem (∇²f̃ of order 1): an
  // objective still changing by more is still on its way, and a warm start that is already within a (common
  // when the force scale is set by a stiff body, far above the contact forces) would otherwise end after ten
  // such iterations, at its first trial accuracy. Iterates at the noise floor change the objective by round-off
  // and still end acceptably.
  const double acceptable = std::max(options.tolerance, std::min(1e-6, 1e4 * options.tolerance));
  set_default(app, "acceptable_tol", acceptable);
  set_default(app, "acceptable_iter", 10);
  set_default(app, "acceptable_obj_change_tol", acceptable * acceptable);
  set_default(app, "nlp_scaling_method", std::string("user-scaling"));
  // IPOPT relaxes every bound by 1e-8·max(1, |bound|) by default, which would let active contact
  // constraints end at c = −1e-8 (in units of x): a visible penetration. Keep the constraints exact.
  set_default(app, "bound_relax_factor", 0.0);
  set_default(app, "jac_c_constant", std::string("yes"));
  set_default(app, "jac_d_constant", std::string("yes"));
  if (problem.hessian_is_constant()) set_default(app, "hessian_constant", std::string("yes"));
  if (warm) {
    // Start at (x0, μ0) itself: push slacks and multipliers off their bounds only a little.
    set_default(app, "warm_start_init_point", std::string("yes"));
    set_default(app, "warm_start_bound_push", 1e-9);
    set_default(app, "warm_start_bound_frac", 1e-9);
    set_default(app, "warm_start_slack_bound_push", 1e-9);
    set_default(app, "warm_start_slack_bound_frac", 1e-9);
    set_default(app, "warm_start_mult_bound_push", 1e-9);
    set_default(app, "mu_init", 1e-9);  // only used by mu_strategy = monotone
  }
}

/// The sizes solve_with_ipopt() is given, checked: std::invalid_argument naming the first that does not fit.
void check_arguments(const ConstrainedProblem& problem, const VectorXd& x0, bool warm, const VectorXd* multipliers0,
                     const VectorXd* bound_multipliers0) {
  const Index n = problem.num_variables();
  const SparseMatrix& A = problem.constraint_matrix();
  const VectorXd& b = problem.constraint_offset();
  if (x0.size() != n)
    throw std::invalid_argument("solve_with_ipopt: x0 has size " + std::to_string(x0.size()) + ", expected " +
                                std::to_string(n));
  if (A.cols() != n || A.rows() != b.size())
    throw std::invalid_argument("solve_with_ipopt: constraint matrix is " + std::to_string(A.rows()) + "x" +
                                std::to_string(A.cols()) + " and offset has size " + std::to_string(b.size()) +
                                " for " + std::to_string(n) + " variables");
  if (n > std::numeric_limits<IpIndex>::max() || A.nonZeros() > std::numeric_limits<IpIndex>::max())
    throw std::invalid_argument("solve_with_ipopt: problem too large for IPOPT's int indices");
  if (warm && multipliers0->size() != A.rows())
    throw std::invalid_argument("solve_with_ipopt: multipliers0 has size " + std::to_string(multipliers0->size()) +
                                ", expected " + std::to_string(A.rows()));
  if (warm && bound_multipliers0 && problem.lower_bounds() && bound_multipliers0->size() != n)
    throw std::invalid_argument("solve_with_ipopt: bound_multipliers0 has size " +
                                std::to_string(bound_multipliers0->size()) + ", expected " + std::to_string(n));
  if (problem.num_equalities() < 0 || problem.num_equalities() > A.rows())
    throw std::invalid_argument("solve_with_ipopt: num_equalities() is outside [0, rows of A]");
  if (problem.lower_bounds() && problem.lower_bounds()->size() != n)
    throw std::invalid_argument("solve_with_ipopt: lower_bounds() does not have the problem size");
}

}  // namespace

/// g_ref = max(‖∇f(x0)‖∞, h·‖x0‖∞) and ℓ = g_ref / h, h = max|∇²f(x0)|; see the header.
ProblemScales problem_scales(const VectorXd& x0, const VectorXd& g0, const SparseMatrix& H0) {
  double h_max = 0.0;
  for (Eigen::Index k = 0; k < H0.nonZeros(); ++k) h_max = std::max(h_max, std::abs(H0.valuePtr()[k]));
  const double g_inf = g0.size() ? g0.lpNorm<Eigen::Infinity>() : 0.0;
  const double x_inf = x0.size() ? x0.lpNorm<Eigen::Infinity>() : 0.0;
  ProblemScales s;
  const double g_ref = std::max(g_inf, h_max * x_inf);
  if (!(g_ref > 0.0) || !std::isfinite(g_ref)) return s;
  s.force = g_ref;
  const double ell = g_ref / h_max;
  if (ell > 0.0 && std::isfinite(ell)) s.length = ell;
  return s;
}

IpoptResult solve_with_ipopt(ConstrainedProblem& problem, const VectorXd& x0, const IpoptOptions& options,
                             const VectorXd* multipliers0, const VectorXd* bound_multipliers0) {
  const Index n = problem.num_variables();
  const SparseMatrix& A = problem.constraint_matrix();
  const VectorXd& b = problem.constraint_offset();
  const bool warm = options.warm_start && multipliers0 != nullptr;
  check_arguments(problem, x0, warm, multipliers0, bound_multipliers0);

  IpoptResult result;
  result.x = x0;
  result.constraint_values = A * x0 + b;
  result.multipliers = VectorXd::Zero(A.rows());
  result.bound_multipliers = VectorXd::Zero(n);

  // Gradient and Hessian at x0: the scaling and the (fixed) Hessian pattern.
  AdapterSetup setup;
  setup.x0 = x0;
  setup.multipliers0 = warm ? multipliers0 : nullptr;
  if (warm && bound_multipliers0 && problem.lower_bounds()) setup.bound_multipliers0 = bound_multipliers0;
  {
    VectorXd g0;
    try {
      problem.gradient(x0, g0);
      problem.hessian_lower(x0, setup.hessian0);
    } catch (const EvaluationError& e) {
      result.status = Ipopt::Invalid_Number_Detected;
      result.status_text = std::string("Evaluation_Error_At_Starting_Point: ") + e.what();
      return result;
    }
    setup.hessian0.makeCompressed();
    if (setup.hessian0.rows() != n || setup.hessian0.cols() != n || g0.size() != n)
      throw std::invalid_argument("solve_with_ipopt: gradient/Hessian at x0 do not have the problem size");
    setup.scales = problem_scales(x0, g0, setup.hessian0);
  }
  result.scales = setup.scales;

  // Console output only when asked for: no console journal at all at print level 0, so not even
  // IPOPT's messages about rejected options reach stdout.
  int print_level = options.print_level;
  if (auto it = options.integer_options.find("print_level"); it != options.integer_options.end())
    print_level = it->second;
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = new Ipopt::IpoptApplication(print_level > 0);
  app->RethrowNonIpoptException(true);  // our std::logic_error etc. must not be swallowed

  set_defaults(*app, options, problem, setup.scales, warm);

  // ---- user options, last so that they override ----
  set_user_options(*app, options);

  // Initialize("") reads no ipopt.opt file from the working directory: all options come from here.
  Ipopt::ApplicationReturnStatus status = app->Initialize("");
  if (status != Ipopt::Solve_Succeeded) {
    result.status = status;
    result.status_text = status_name(status);
    if (status == Ipopt::Invalid_Option)
      throw std::invalid_argument("solve_with_ipopt: IPOPT rejected the options at initialisation (" +
                                  result.status_text + ")");
    return result;
  }

  Ipopt::SmartPtr<ContactTNLP> tnlp = new ContactTNLP(problem, std::move(setup), result);
  const double t0 = wall_seconds();
  restart_ordering_sequence();  // the same orderings, and digits, whatever was solved before (ordering_seed.hpp)
  status = app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(Ipopt::GetRawPtr(tnlp)));
  result.seconds = wall_seconds() - t0;

  result.status = status;
  result.status_text = status_name(status);
  result.success = status == Ipopt::Solve_Succeeded || status == Ipopt::Solved_To_Acceptable_Level;
  if (Ipopt::IsValid(app->Statistics())) result.iterations = app->Statistics()->IterationCount();
  if (!tnlp->finalized()) {  // IPOPT stopped before producing an iterate: report x0
    try {
      result.objective = problem.objective(result.x);
    } catch (const EvaluationError&) {
      result.objective = std::numeric_limits<double>::quiet_NaN();
    }
  }
  return result;
}

void check_ipopt_options(const IpoptOptions& options) {
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = new Ipopt::IpoptApplication(false);  // no console output
  set_user_options(*app, options);
}

}  // namespace symcontact
