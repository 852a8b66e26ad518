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

/// The sums, kept as the outer product they are: neighbour j adds weight_r * u_c with
/// weight = (W, F dx, F dy, F dz) and u = V (1, dx, dy, dz) followed by m and V (vx, vy, vz).
/// Columns 0-3 are the matrix above, column 4 the density's right-hand side, 5-7 the
/// velocity components'. Four rows of eight doubles: one vector multiply-add per row and
/// neighbour (the CPU's mDBC pass is the costliest loop of a case with many wall particles).
struct GhostSums {
  static constexpr int kRho = 4, kVel = 5;  ///< first column of each right-hand side
  double s[4][8] = {};
  /// The matrix entry (r, c), unknown order (f, df/dx, df/dy, df/dz).
  NETSPH_HD double a(int r, int c) const { return s[r][c]; }
};

/// What neighbour j adds to the sums: d = r_j - r_g, w = W(|d|), f = F(|d|), mass and state of j.
struct GhostTerms {
  double weight[4];  ///< (W, F dx, F dy, F dz)
  double u[8];       ///< V (1, dx, dy, dz), m, V (vx, vy, vz)
};

NETSPH_HD GhostTerms ghost_terms(const Vec3f& d, Real w, Real f, Real mass, Real rho,
                                 const Vec3f& v) {
  const double vol = static_cast<double>(mass) / static_cast<double>(rho);
  const double fd = f;
  return {{static_cast<double>(w), fd * d.x, fd * d.y, fd * d.z},
          {vol, vol * d.x, vol * d.y, vol * d.z, static_cast<double>(mass), vol * v.x, vol * v.y,
           vol * v.z}};
}

/// s += weight (x) u.
NETSPH_HD void ghost_add(GhostSums& s, const double (&weight)[4], const double (&u)[8]) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 8; ++c) s.s[r][c] += weight[r] * u[c];
}

/// Adds neighbour j (the arguments of ghost_terms).
NETSPH_HD void ghost_accumulate(GhostSums& s, const Vec3f& d, Real w, Real f, Real mass, Real rho,
                                const Vec3f& v) {
  const GhostTerms t = ghost_terms(d, w, f, mass, rho, v);
  ghost_add(s, t.weight, t.u);
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
  const double sum_vw = s.a(0, 0);
  if (!(sum_vw > 0)) return g;
  g.any = true;
  // Zeroth order first: the fallback, and the answer when the matrix is singular.
  const double* row0 = s.s[0];
  g.rho = row0[GhostSums::kRho] / sum_vw;
  g.vel = {row0[GhostSums::kVel] / sum_vw, row0[GhostSums::kVel + 1] / sum_vw,
           row0[GhostSums::kVel + 2] / sum_vw};

  const int idx3[4] = {0, 1, 2, 3}, idx2[3] = {0, 1, 3};
  const int* idx = dims == 2 ? idx2 : idx3;
  const int n = dims == 2 ? 3 : 4;
  double m[4][4] = {}, rhs[4][4] = {};
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) m[r][c] = s.a(idx[r], idx[c]);
    rhs[0][r] = s.s[idx[r]][GhostSums::kRho];
    for (int k = 0; k < 3; ++k) rhs[k + 1][r] = s.s[idx[r]][GhostSums::kVel + k];
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
