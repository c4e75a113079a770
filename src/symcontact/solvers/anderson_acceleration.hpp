#pragma once
/// \file anderson_acceleration.hpp
/// Anderson acceleration of a fixed-point iteration x ← G(x).
///
/// Anderson (1965, J. ACM 12(4), 547–560), in the form of Walker & Ni (2011, SIAM J. Numer. Anal. 49(4),
/// 1715–1735, Algorithm AA with mixing β = 1): with the residuals f_j = G(x_j) − x_j and the last m
/// differences of the residuals and of the images,
///     ΔF = [f_{j+1} − f_j],   ΔG = [G(x_{j+1}) − G(x_j)]   (n × k, k ≤ m, oldest first),
///     γ = argmin_γ ‖f_k − ΔF γ‖₂,   x_{k+1} = G(x_k) − ΔG γ.
/// With no history (k = 0) the step is the plain one, x_{k+1} = G(x_k). For an affine map G(x) = J x + c
/// the iterates are those of GMRES on (I − J) x = c (Walker & Ni, Theorem 2.2, with full memory), so the
/// iteration converges also when J has eigenvalues outside the unit disc (a growing mode of the plain
/// iteration), as long as they are few compared with the memory.
///
/// The history must only span iterates of one smooth map: restart (reset()) when the map changes (for the
/// contact geometry fixed point: other constraint rows, another active set).

#include <deque>

#include "symcontact/core/types.hpp"

namespace symcontact {

class AndersonAcceleration {
 public:
  /// memory m ≥ 1: the number of difference columns kept.
  explicit AndersonAcceleration(int memory);

  /// Given the iterate x = x_k and its image g = G(x_k) (same size), records them and returns x_{k+1}.
  VectorXd next(const VectorXd& x, const VectorXd& g);

  /// Forgets the history: the next call returns its g.
  void reset();

  /// Number of difference columns held (0 after reset() and after the first call).
  int columns() const { return static_cast<int>(dF_.size()); }

 private:
  int memory_;
  bool has_previous_ = false;
  VectorXd f_prev_, g_prev_;
  std::deque<VectorXd> dF_, dG_;
};

}  // namespace symcontact
