// SPDX-License-Identifier: BSD-3-Clause
/// Our MINPACK: the Levenberg-Marquardt least-squares solver of Moré, Garbow and Hillstrom
/// (the routines VXL's v3p_netlib carries under vnl_levenberg_marquardt), written from Moré's
/// published description ("The Levenberg-Marquardt algorithm: implementation and theory",
/// 1978, and the MINPACK-1 user guide) and templated on the scalar T.
///
/// Faithfulness: in double every routine performs MINPACK's operations in MINPACK's order, so
/// iteration and evaluation counts equal upstream's (tests/host/minpack checks this against
/// cminpack). Machine constants come from std::numeric_limits<T> (see minpack_machine), so a
/// fixed-point T gets its own epsilon and range, never double's.
///
/// Conventions (as cminpack's C interface, with one difference): matrices are column-major,
/// element (i, j) at a[i + j * lda]; the callback gets an opaque pointer; ipvt is 0-based here
/// (column j of the permutation is column ipvt[j] of the identity), where cminpack's is 1-based.
#pragma once

inline namespace edgetrack_ports {

namespace netlib {

/// Residuals callback for lmdif: fill fvec (m) at x (n). iflag is 1 or 2 for an evaluation,
/// 0 for the optional progress call; return a negative value to stop the solver.
template <class T>
using minpack_func_mn = int (*)(void* p, int m, int n, const T* x, T* fvec, int iflag);

/// Residuals-and-Jacobian callback for lmder: iflag 1 fills fvec, iflag 2 fills fjac (m x n,
/// column-major, leading dimension ldfjac), iflag 0 is the progress call. Negative return stops.
template <class T>
using minpack_funcder_mn = int (*)(void* p, int m, int n, const T* x, T* fvec, T* fjac, int ldfjac, int iflag);

/// The machine constants MINPACK's dpmpar and enorm use, derived from std::numeric_limits<T>.
template <class T>
struct minpack_machine {
  T epsmch;  ///< epsilon(): one ulp for fixed point
  T dwarf;   ///< min(): the smallest positive magnitude
  T rdwarf;  ///< 0.9 sqrt(min()): below it a square would underflow; enorm rescales
  T rgiant;  ///< 0.9 sqrt(max()): above it a square would overflow; enorm rescales
};

/// Computes the constants for T (a few operations in T; call once per solve).
template <class T>
minpack_machine<T> minpack_machine_constants();

/// Euclidean norm of x[0..n), without destructive underflow or overflow (three scaled sums; for
/// a fixed-point T, which has neither, fixedpoint::euclidean_norm's exact sum of raw squares).
template <class T>
T enorm(int n, const T* x);
template <class T>
T enorm(int n, const T* x, const minpack_machine<T>& machine);

/// Householder QR of the m x n matrix a with optional column pivoting. On return the strict
/// upper triangle of a holds R's off-diagonal, rdiag its diagonal, the lower trapezoid the
/// Householder vectors; acnorm holds the column norms of the input; wa is work (n).
template <class T>
void qrfac(int m, int n, T* a, int lda, bool pivot, int* ipvt, T* rdiag, T* acnorm, T* wa,
           const minpack_machine<T>& machine);

/// Solves the least-squares system [A; D] x = [b; 0] given A P = Q R (full upper triangle of r)
/// and qtb = the first n of Q^T b. r's lower triangle receives S, sdiag S's diagonal, where
/// P^T (A^T A + D D) P = S^T S. wa is work (n).
template <class T>
void qrsolv(int n, T* r, int ldr, const int* ipvt, const T* diag, const T* qtb, T* x, T* sdiag, T* wa,
            const minpack_machine<T>& machine);

/// The Levenberg-Marquardt parameter par for step bound delta: x solves the damped system and
/// |diag * x| is within 10% of delta (or par is 0 and the Gauss-Newton step is short enough).
template <class T>
void lmpar(int n, T* r, int ldr, const int* ipvt, const T* diag, const T* qtb, T delta, T* par, T* x, T* sdiag, T* wa1,
           T* wa2, const minpack_machine<T>& machine);

/// Forward-difference Jacobian of fcn at x (fvec = f(x)); wa is work (m). Returns fcn's last
/// return value (negative when it asked to stop).
template <class T>
int fdjac2(minpack_func_mn<T> fcn, void* p, int m, int n, T* x, const T* fvec, T* fjac, int ldfjac, T epsfcn, T* wa,
           const minpack_machine<T>& machine);

/// Minimises the sum of squares of m residuals in n unknowns with an analytic Jacobian.
/// Returns MINPACK's info: 0 bad input, 1 ftol, 2 xtol, 3 both, 4 gtol, 5 maxfev reached,
/// 6/7/8 ftol/xtol/gtol below machine precision, or the callback's negative value.
/// nfev counts residual evaluations and njev Jacobian evaluations (= iterations).
template <class T>
int lmder(minpack_funcder_mn<T> fcn, void* p, int m, int n, T* x, T* fvec, T* fjac, int ldfjac, T ftol, T xtol, T gtol,
          int maxfev, T* diag, int mode, T factor, int nprint, int* nfev, int* njev, int* ipvt, T* qtf, T* wa1, T* wa2,
          T* wa3, T* wa4);

/// As lmder, with the Jacobian from forward differences of step sqrt(max(epsfcn, epsmch))
/// relative to each x[j]; nfev includes the n evaluations per Jacobian.
template <class T>
int lmdif(minpack_func_mn<T> fcn, void* p, int m, int n, T* x, T* fvec, T ftol, T xtol, T gtol, int maxfev, T epsfcn,
          T* diag, int mode, T factor, int nprint, int* nfev, T* fjac, int ldfjac, int* ipvt, T* qtf, T* wa1, T* wa2,
          T* wa3, T* wa4);

}  // namespace netlib

}  // inline namespace edgetrack_ports
