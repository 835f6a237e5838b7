// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_rnpoly_solve.h"

#include <algorithm>
#include <cmath>
#include <complex>

inline namespace edgetrack_ports {

namespace {

using C = std::complex<double>;
using CVector = std::vector<C>;

constexpr double kDivergence = 1e12;  // |x| beyond which a path goes to infinity

/// The system f, and the homotopy H(x, t) = (1 - t) gamma g(x) + t f(x) with g_i = x_i^d_i - 1.
class Homotopy {
 public:
  explicit Homotopy(const std::vector<vnl_real_npolynomial*>& ps) : ps_(ps), n_(ps.size()) {
    for (const vnl_real_npolynomial* p : ps_) degrees_.push_back(std::max(1u, p->degree()));
  }
  unsigned size() const { return n_; }
  const std::vector<unsigned>& degrees() const { return degrees_; }

  /// f(x) and its Jacobian (row i: d f_i / d x).
  void system(const CVector& x, CVector& f, std::vector<CVector>& J) const {
    for (unsigned i = 0; i < n_; ++i) {
      const vnl_vector<double>& c = ps_[i]->coefficients();
      const vnl_matrix<unsigned int>& p = ps_[i]->polyn();
      f[i] = 0;
      std::fill(J[i].begin(), J[i].end(), C(0));
      for (unsigned k = 0; k < c.size(); ++k) {
        C term = c[k];
        for (unsigned j = 0; j < n_; ++j) term *= std::pow(x[j], static_cast<int>(p(k, j)));
        f[i] += term;
        for (unsigned j = 0; j < n_; ++j) {
          if (p(k, j) == 0) continue;
          C partial = c[k] * double(p(k, j)) * std::pow(x[j], static_cast<int>(p(k, j)) - 1);
          for (unsigned l = 0; l < n_; ++l)
            if (l != j) partial *= std::pow(x[l], static_cast<int>(p(k, l)));
          J[i][j] += partial;
        }
      }
    }
  }

  /// H(x, t), dH/dx and dH/dt.
  void at(const CVector& x, double t, CVector& h, std::vector<CVector>& Hx, CVector& Ht) const {
    system(x, h, Hx);
    for (unsigned i = 0; i < n_; ++i) {
      const C g = std::pow(x[i], static_cast<int>(degrees_[i])) - C(1);
      const C dg = double(degrees_[i]) * std::pow(x[i], static_cast<int>(degrees_[i]) - 1);
      Ht[i] = h[i] - kGamma * g;
      h[i] = (1 - t) * kGamma * g + t * h[i];
      for (unsigned j = 0; j < n_; ++j) Hx[i][j] *= t;
      Hx[i][i] += (1 - t) * kGamma * dg;
    }
  }

 private:
  // A fixed generic complex constant keeps every path away from singularities for t < 1.
  inline static const C kGamma = std::polar(1.0, 2.1763);
  const std::vector<vnl_real_npolynomial*>& ps_;
  unsigned n_;
  std::vector<unsigned> degrees_;
};

/// Solves A d = b by Gaussian elimination with partial pivoting; false when A is singular.
template <class T>
bool solve(std::vector<std::vector<T>> A, std::vector<T> b, std::vector<T>& d) {
  const size_t n = b.size();
  for (size_t k = 0; k < n; ++k) {
    size_t best = k;
    for (size_t i = k + 1; i < n; ++i)
      if (std::abs(A[i][k]) > std::abs(A[best][k])) best = i;
    if (std::abs(A[best][k]) == 0) return false;
    std::swap(A[k], A[best]);
    std::swap(b[k], b[best]);
    for (size_t i = k + 1; i < n; ++i) {
      const T factor = A[i][k] / A[k][k];
      for (size_t j = k; j < n; ++j) A[i][j] -= factor * A[k][j];
      b[i] -= factor * b[k];
    }
  }
  d.assign(n, T(0));
  for (size_t i = n; i-- > 0;) {
    T v = b[i];
    for (size_t j = i + 1; j < n; ++j) v -= A[i][j] * d[j];
    d[i] = v / A[i][i];
  }
  return true;
}

double norm(const CVector& v) {
  double s = 0;
  for (const C& x : v) s += std::norm(x);
  return std::sqrt(s);
}

/// Follows one path from t = 0 to t = 1; false when it diverges or the step collapses.
bool track(const Homotopy& H, CVector& x) {
  const unsigned n = H.size();
  CVector h(n), Ht(n), dx, predicted;
  std::vector<CVector> Hx(n, CVector(n));
  double t = 0, step = 0.01;
  int steps = 0;
  while (t < 1) {
    // Steps shrink as far as the arithmetic allows: a badly scaled system moves its paths
    // within the first 1e-15 of t.
    const double next_t = std::min(1.0, t + step);
    if (next_t == t) return false;
    H.at(x, t, h, Hx, Ht);
    CVector minus_ht(n);
    for (unsigned i = 0; i < n; ++i) minus_ht[i] = -Ht[i];
    if (!solve(Hx, minus_ht, dx)) return false;
    predicted = x;
    for (unsigned i = 0; i < n; ++i) predicted[i] += (next_t - t) * dx[i];
    bool converged = false;
    for (int iteration = 0; iteration < 4 && !converged; ++iteration) {
      H.at(predicted, next_t, h, Hx, Ht);
      CVector minus_h(n);
      for (unsigned i = 0; i < n; ++i) minus_h[i] = -h[i];
      if (!solve(Hx, minus_h, dx)) break;
      for (unsigned i = 0; i < n; ++i) predicted[i] += dx[i];
      converged = norm(dx) <= 1e-10 * (1 + norm(predicted));
    }
    if (!converged) {
      step /= 2;
      continue;
    }
    if (++steps > 100000) return false;
    x = predicted;
    t = next_t;
    step = std::min(step * 1.5, 0.05);
    if (norm(x) > kDivergence) return false;
  }
  return true;
}

/// Newton's method on f in real arithmetic from x; true when it converges.
bool polish_real(const Homotopy& H, std::vector<double>& x) {
  const unsigned n = H.size();
  CVector cx(n), f(n);
  std::vector<CVector> J(n, CVector(n));
  for (int iteration = 0; iteration < 20; ++iteration) {
    for (unsigned i = 0; i < n; ++i) cx[i] = x[i];
    H.system(cx, f, J);
    std::vector<std::vector<double>> A(n, std::vector<double>(n));
    std::vector<double> b(n), d;
    for (unsigned i = 0; i < n; ++i) {
      b[i] = -f[i].real();
      for (unsigned j = 0; j < n; ++j) A[i][j] = J[i][j].real();
    }
    if (!solve(A, b, d)) return false;
    double step = 0, size = 0;
    for (unsigned i = 0; i < n; ++i) {
      x[i] += d[i];
      step += d[i] * d[i];
      size += x[i] * x[i];
    }
    if (std::sqrt(step) <= 1e-14 * (1 + std::sqrt(size))) return true;
  }
  return false;
}

}  // namespace

bool vnl_rnpoly_solve::compute() {
  const Homotopy H(ps_);
  const unsigned n = H.size();
  if (n == 0) return false;
  for (const vnl_real_npolynomial* p : ps_)
    if (p->polyn().cols() != n) return false;  // not square
  // Start points: every combination of the d_i-th roots of unity.
  std::vector<unsigned> index(n, 0);
  const double two_pi = 2 * std::acos(-1.0);
  while (true) {
    CVector x(n);
    for (unsigned i = 0; i < n; ++i) x[i] = std::polar(1.0, two_pi * index[i] / H.degrees()[i]);
    if (track(H, x)) {
      // Newton on f at t = 1, then a real polish when the imaginary part is negligible.
      CVector f(n), dx;
      std::vector<CVector> J(n, CVector(n));
      for (int iteration = 0; iteration < 10; ++iteration) {
        H.system(x, f, J);
        for (C& v : f) v = -v;
        if (!solve(J, f, dx)) break;
        for (unsigned i = 0; i < n; ++i) x[i] += dx[i];
        if (norm(dx) <= 1e-15 * (1 + norm(x))) break;
      }
      double imaginary = 0;
      for (const C& v : x) imaginary = std::max(imaginary, std::fabs(v.imag()));
      std::vector<double> real_part(n);
      for (unsigned i = 0; i < n; ++i) real_part[i] = x[i].real();
      const bool real_root = imaginary <= 1e-7 * (1 + norm(x)) && polish_real(H, real_part);
      auto re = std::make_unique<vnl_vector<double>>(n), im = std::make_unique<vnl_vector<double>>(n, 0.0);
      for (unsigned i = 0; i < n; ++i) {
        (*re)[i] = real_root ? real_part[i] : x[i].real();
        (*im)[i] = real_root ? 0.0 : x[i].imag();
      }
      r_.push_back(re.get());
      i_.push_back(im.get());
      storage_.push_back(std::move(re));
      storage_.push_back(std::move(im));
    }
    unsigned k = 0;  // the next combination
    while (k < n && ++index[k] == H.degrees()[k]) index[k++] = 0;
    if (k == n) break;
  }
  return true;
}

std::vector<vnl_vector<double>*> vnl_rnpoly_solve::realroots(double tol) {
  std::vector<vnl_vector<double>*> roots;
  for (size_t k = 0; k < r_.size(); ++k)
    if (i_[k]->squared_magnitude() < tol * tol) roots.push_back(r_[k]);
  return roots;
}

}  // inline namespace edgetrack_ports
