#pragma once
// First-order consistent SPH interpolation at a point that is not a particle (a "ghost
// node"), after Liu & Liu (2006), as mDBC (English et al. 2022) and the open boundaries of
// Tafuni et al. (2018) use it. With d_j = r_j - r_g and the weights W_j, F_j d_j
// (F = (1/r) dW/dr), the Taylor expansion f_j = f_g + grad f . d_j summed against both gives
//
//   [ sum V W       sum V W d^T   ] [ f_g    ]   [ sum V W f   ]
//   [ sum V F d     sum V F d d^T ] [ grad f ] = [ sum V F d f ]
//
// (V_j = m_j / rho_j; for the density V_j rho_j = m_j). Inside the fluid the matrix is about
// diag(1, -1, -1, -1), so |det| ~ 1; when the ghost node sees too few particles the system
// is singular and the zeroth-order Shepard value sum V W f / sum V W is used instead
// (|det| < 1e-3, English et al. 2022). Sums are in double: they run only for boundary and
// buffer particles, and the 4x4 solve needs the precision.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

struct GhostSums {
  double a[4][4] = {};    ///< the matrix above, unknown order (f, df/dx, df/dy, df/dz)
  double rho[4] = {};     ///< right-hand side for the density
  double vel[3][4] = {};  ///< right-hand sides for the velocity components
};

/// Adds neighbour j: d = r_j - r_g, w = W(|d|), f = F(|d|), mass and state of j.
NETSPH_HD void ghost_accumulate(GhostSums& s, const Vec3f& d, Real w, Real f, Real mass, Real rho,
                                const Vec3f& v) {
  const double vol = static_cast<double>(mass) / static_cast<double>(rho);
  const double row0[4] = {w, w * d.x, w * d.y, w * d.z};
  const double fd[3] = {static_cast<double>(f) * d.x, static_cast<double>(f) * d.y,
                        static_cast<double>(f) * d.z};
  for (int c = 0; c < 4; ++c) s.a[0][c] += vol * row0[c];
  for (int r = 0; r < 3; ++r) {
    s.a[r + 1][0] += vol * fd[r];
    s.a[r + 1][1] += vol * fd[r] * d.x;
    s.a[r + 1][2] += vol * fd[r] * d.y;
    s.a[r + 1][3] += vol * fd[r] * d.z;
  }
  const double weight[4] = {w, fd[0], fd[1], fd[2]};
  const double vj[3] = {v.x, v.y, v.z};
  for (int r = 0; r < 4; ++r) {
    s.rho[r] += static_cast<double>(mass) * weight[r];
    for (int c = 0; c < 3; ++c) s.vel[c][r] += vol * weight[r] * vj[c];
  }
}

struct GhostValue {
  bool any = false;          ///< the ghost saw at least one particle
  bool first_order = false;  ///< |det| passed the limit: gradients are valid
  double rho = 0;
  Vec3d grad_rho{};
  Vec3d vel{};
  Vec3d grad_vel[3] = {};  ///< gradient of each velocity component
};

namespace detail {
/// Solves the n x n system m x = b for several right-hand sides by Gaussian elimination with
/// partial pivoting; returns the determinant (0 when singular).
NETSPH_HD double solve_small(int n, double m[4][4], double rhs[4][4], int nrhs) {
  double det = 1;
  for (int col = 0; col < n; ++col) {
    int piv = col;
    for (int r = col + 1; r < n; ++r)
      if (std::fabs(m[r][col]) > std::fabs(m[piv][col])) piv = r;
    if (m[piv][col] == 0) return 0;
    if (piv != col) {
      for (int c = 0; c < n; ++c) {
        const double t = m[col][c];
        m[col][c] = m[piv][c];
        m[piv][c] = t;
      }
      for (int k = 0; k < nrhs; ++k) {
        const double t = rhs[k][col];
        rhs[k][col] = rhs[k][piv];
        rhs[k][piv] = t;
      }
      det = -det;
    }
    det *= m[col][col];
    for (int r = col + 1; r < n; ++r) {
      const double f = m[r][col] / m[col][col];
      for (int c = col; c < n; ++c) m[r][c] -= f * m[col][c];
      for (int k = 0; k < nrhs; ++k) rhs[k][r] -= f * rhs[k][col];
    }
  }
  for (int k = 0; k < nrhs; ++k)
    for (int r = n - 1; r >= 0; --r) {
      double acc = rhs[k][r];
      for (int c = r + 1; c < n; ++c) acc -= m[r][c] * rhs[k][c];
      rhs[k][r] = acc / m[r][r];
    }
  return det;
}
}  // namespace detail

/// Density (and velocity) at the ghost node. In 2D the y row and column are dropped.
NETSPH_HD GhostValue ghost_solve(const GhostSums& s, int dims, double det_limit = 1e-3) {
  GhostValue g;
  const double sum_vw = s.a[0][0];
  if (!(sum_vw > 0)) return g;
  g.any = true;
  // Zeroth order first: the fallback, and the answer when the matrix is singular.
  g.rho = s.rho[0] / sum_vw;
  g.vel = {s.vel[0][0] / sum_vw, s.vel[1][0] / sum_vw, s.vel[2][0] / sum_vw};

  const int idx3[4] = {0, 1, 2, 3}, idx2[3] = {0, 1, 3};
  const int* idx = dims == 2 ? idx2 : idx3;
  const int n = dims == 2 ? 3 : 4;
  double m[4][4] = {}, rhs[4][4] = {};
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) m[r][c] = s.a[idx[r]][idx[c]];
    rhs[0][r] = s.rho[idx[r]];
    for (int k = 0; k < 3; ++k) rhs[k + 1][r] = s.vel[k][idx[r]];
  }
  const double det = detail::solve_small(n, m, rhs, 4);
  if (!(std::fabs(det) >= det_limit)) return g;
  g.first_order = true;
  auto grad = [&](const double* x) {
    return dims == 2 ? Vec3d(x[1], 0, x[2]) : Vec3d(x[1], x[2], x[3]);
  };
  g.rho = rhs[0][0];
  g.grad_rho = grad(rhs[0]);
  g.vel = {rhs[1][0], rhs[2][0], rhs[3][0]};
  for (int k = 0; k < 3; ++k) g.grad_vel[k] = grad(rhs[k + 1]);
  return g;
}

}  // namespace netsph
