// SPDX-License-Identifier: BSD-3-Clause
/// The Moré–Garbow–Hillstrom least-squares test problems ("Testing unconstrained optimization
/// software", ACM TOMS 7, 1981) that MINPACK's own test driver uses, templated on the scalar,
/// with analytic Jacobians, standard starting points and the published minima. Shared by the
/// portable MINPACK tests (tests/ports/netlib) and the host comparison with cminpack
/// (tests/host/minpack). Data are compile-time constants of T, so fixed-point runs convert no
/// double while evaluating.
#pragma once

#include <cmath>
#include <memory>
#include <vector>

namespace mgh {

template <class T>
class Problem {
 public:
  virtual ~Problem() = default;
  virtual const char* name() const = 0;
  virtual int m() const = 0;
  virtual int n() const = 0;
  /// The standard starting point.
  virtual std::vector<double> start() const = 0;
  /// The residuals f (size m) at x (size n).
  virtual void residuals(const T* x, T* f) const = 0;
  /// The Jacobian, column-major with leading dimension ld: fjac[i + j * ld] = d f_i / d x_j.
  virtual void jacobian(const T* x, T* fjac, int ld) const = 0;
  /// The published minimal sum of squares (the local one reached from the standard start).
  virtual double minimum() const = 0;
  /// The published minimiser, or empty where it is not unique.
  virtual std::vector<double> minimiser() const { return {}; }
};

template <class T>
class Rosenbrock final : public Problem<T> {
 public:
  const char* name() const override { return "Rosenbrock"; }
  int m() const override { return 2; }
  int n() const override { return 2; }
  std::vector<double> start() const override { return {-1.2, 1}; }
  void residuals(const T* x, T* f) const override {
    f[0] = T(10) * (x[1] - x[0] * x[0]);
    f[1] = T(1) - x[0];
  }
  void jacobian(const T* x, T* J, int ld) const override {
    J[0] = T(-20) * x[0];
    J[1] = T(-1);
    J[ld] = T(10);
    J[ld + 1] = T(0);
  }
  double minimum() const override { return 0; }
  std::vector<double> minimiser() const override { return {1, 1}; }
};

template <class T>
class PowellSingular final : public Problem<T> {
  static constexpr T kSqrt5 = T(2.2360679774997896964);
  static constexpr T kSqrt10 = T(3.1622776601683793320);

 public:
  const char* name() const override { return "Powell singular"; }
  int m() const override { return 4; }
  int n() const override { return 4; }
  std::vector<double> start() const override { return {3, -1, 0, 1}; }
  void residuals(const T* x, T* f) const override {
    const T a = x[1] - T(2) * x[2];
    const T b = x[0] - x[3];
    f[0] = x[0] + T(10) * x[1];
    f[1] = kSqrt5 * (x[2] - x[3]);
    f[2] = a * a;
    f[3] = kSqrt10 * (b * b);
  }
  void jacobian(const T* x, T* J, int ld) const override {
    const T a = x[1] - T(2) * x[2];
    const T b = x[0] - x[3];
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) J[i + j * ld] = T(0);
    }
    J[0] = T(1);
    J[ld] = T(10);
    J[1 + 2 * ld] = kSqrt5;
    J[1 + 3 * ld] = -kSqrt5;
    J[2 + ld] = T(2) * a;
    J[2 + 2 * ld] = T(-4) * a;
    J[3] = T(2) * kSqrt10 * b;
    J[3 + 3 * ld] = T(-2) * kSqrt10 * b;
  }
  double minimum() const override { return 0; }
  std::vector<double> minimiser() const override { return {0, 0, 0, 0}; }
};

template <class T>
class FreudensteinRoth final : public Problem<T> {
 public:
  const char* name() const override { return "Freudenstein-Roth"; }
  int m() const override { return 2; }
  int n() const override { return 2; }
  std::vector<double> start() const override { return {0.5, -2}; }
  void residuals(const T* x, T* f) const override {
    f[0] = T(-13) + x[0] + ((T(5) - x[1]) * x[1] - T(2)) * x[1];
    f[1] = T(-29) + x[0] + ((x[1] + T(1)) * x[1] - T(14)) * x[1];
  }
  void jacobian(const T* x, T* J, int ld) const override {
    J[0] = T(1);
    J[1] = T(1);
    J[ld] = x[1] * (T(10) - T(3) * x[1]) - T(2);
    J[ld + 1] = x[1] * (T(3) * x[1] + T(2)) - T(14);
  }
  double minimum() const override { return 48.9842536792400; }
  std::vector<double> minimiser() const override { return {11.4127789869, -0.896805253}; }
};

template <class T>
class Bard final : public Problem<T> {
  static constexpr T kY[15] = {T(0.14), T(0.18), T(0.22), T(0.25), T(0.29), T(0.32), T(0.35), T(0.39),
                               T(0.37), T(0.58), T(0.73), T(0.96), T(1.34), T(2.10), T(4.39)};

 public:
  const char* name() const override { return "Bard"; }
  int m() const override { return 15; }
  int n() const override { return 3; }
  std::vector<double> start() const override { return {1, 1, 1}; }
  void residuals(const T* x, T* f) const override {
    for (int i = 0; i < 15; ++i) {
      const int u = i + 1, v = 15 - i, w = u < v ? u : v;
      f[i] = kY[i] - (x[0] + T(u) / (T(v) * x[1] + T(w) * x[2]));
    }
  }
  void jacobian(const T* x, T* J, int ld) const override {
    for (int i = 0; i < 15; ++i) {
      const int u = i + 1, v = 15 - i, w = u < v ? u : v;
      const T d = T(v) * x[1] + T(w) * x[2];
      const T ud2 = T(u) / (d * d);
      J[i] = T(-1);
      J[i + ld] = T(v) * ud2;
      J[i + 2 * ld] = T(w) * ud2;
    }
  }
  double minimum() const override { return 8.21487730657e-3; }
  std::vector<double> minimiser() const override { return {0.0824105597, 1.13303609, 2.34369506}; }
};

template <class T>
class KowalikOsborne final : public Problem<T> {
  static constexpr T kY[11] = {T(0.1957), T(0.1947), T(0.1735), T(0.1600), T(0.0844), T(0.0627),
                               T(0.0456), T(0.0342), T(0.0323), T(0.0235), T(0.0246)};
  static constexpr T kU[11] = {T(4),     T(2),   T(1),      T(0.5),    T(0.25),  T(0.167),
                               T(0.125), T(0.1), T(0.0833), T(0.0714), T(0.0625)};

 public:
  const char* name() const override { return "Kowalik-Osborne"; }
  int m() const override { return 11; }
  int n() const override { return 4; }
  std::vector<double> start() const override { return {0.25, 0.39, 0.415, 0.39}; }
  void residuals(const T* x, T* f) const override {
    for (int i = 0; i < 11; ++i) {
      const T u = kU[i];
      f[i] = kY[i] - x[0] * (u * (u + x[1])) / (u * (u + x[2]) + x[3]);
    }
  }
  void jacobian(const T* x, T* J, int ld) const override {
    for (int i = 0; i < 11; ++i) {
      const T u = kU[i];
      const T num = u * (u + x[1]);
      const T den = u * (u + x[2]) + x[3];
      const T q = x[0] * num / den / den;
      J[i] = -num / den;
      J[i + ld] = -x[0] * u / den;
      J[i + 2 * ld] = q * u;
      J[i + 3 * ld] = q;
    }
  }
  double minimum() const override { return 3.07505603849e-4; }
  std::vector<double> minimiser() const override { return {0.192806935, 0.191282322, 0.123056508, 0.136062327}; }
};

template <class T>
class Box3d final : public Problem<T> {
 public:
  const char* name() const override { return "Box 3-D"; }
  int m() const override { return 10; }
  int n() const override { return 3; }
  std::vector<double> start() const override { return {0, 10, 20}; }
  void residuals(const T* x, T* f) const override {
    using std::exp;
    for (int i = 0; i < 10; ++i) {
      const T t = T(i + 1) / T(10);
      f[i] = exp(-t * x[0]) - exp(-t * x[1]) - x[2] * (exp(-t) - exp(T(-10) * t));
    }
  }
  void jacobian(const T* x, T* J, int ld) const override {
    using std::exp;
    for (int i = 0; i < 10; ++i) {
      const T t = T(i + 1) / T(10);
      J[i] = -t * exp(-t * x[0]);
      J[i + ld] = t * exp(-t * x[1]);
      J[i + 2 * ld] = -(exp(-t) - exp(T(-10) * t));
    }
  }
  double minimum() const override { return 0; }
  std::vector<double> minimiser() const override { return {1, 10, 1}; }
};

template <class T>
class JennrichSampson final : public Problem<T> {
 public:
  const char* name() const override { return "Jennrich-Sampson"; }
  int m() const override { return 10; }
  int n() const override { return 2; }
  std::vector<double> start() const override { return {0.3, 0.4}; }
  void residuals(const T* x, T* f) const override {
    using std::exp;
    for (int i = 0; i < 10; ++i) {
      const int k = i + 1;
      f[i] = T(2 + 2 * k) - (exp(T(k) * x[0]) + exp(T(k) * x[1]));
    }
  }
  void jacobian(const T* x, T* J, int ld) const override {
    using std::exp;
    for (int i = 0; i < 10; ++i) {
      const int k = i + 1;
      J[i] = -T(k) * exp(T(k) * x[0]);
      J[i + ld] = -T(k) * exp(T(k) * x[1]);
    }
  }
  double minimum() const override { return 124.362182355; }
  std::vector<double> minimiser() const override { return {0.257824781, 0.257824781}; }
};

template <class T>
class BrownDennis final : public Problem<T> {
 public:
  const char* name() const override { return "Brown-Dennis"; }
  int m() const override { return 20; }
  int n() const override { return 4; }
  std::vector<double> start() const override { return {25, 5, -5, -1}; }
  void residuals(const T* x, T* f) const override {
    using std::cos;
    using std::exp;
    using std::sin;
    for (int i = 0; i < 20; ++i) {
      const T t = T(i + 1) / T(5);
      const T a = x[0] + t * x[1] - exp(t);
      const T b = x[2] + x[3] * sin(t) - cos(t);
      f[i] = a * a + b * b;
    }
  }
  void jacobian(const T* x, T* J, int ld) const override {
    using std::cos;
    using std::exp;
    using std::sin;
    for (int i = 0; i < 20; ++i) {
      const T t = T(i + 1) / T(5);
      const T a = x[0] + t * x[1] - exp(t);
      const T b = x[2] + x[3] * sin(t) - cos(t);
      J[i] = T(2) * a;
      J[i + ld] = T(2) * a * t;
      J[i + 2 * ld] = T(2) * b;
      J[i + 3 * ld] = T(2) * b * sin(t);
    }
  }
  double minimum() const override { return 85822.2016263563; }
  std::vector<double> minimiser() const override { return {-11.5944399, 13.2036301, -0.403439442, 0.236778970}; }
};

template <class T>
class Osborne1 final : public Problem<T> {
  static constexpr T kY[33] = {T(0.844), T(0.908), T(0.932), T(0.936), T(0.925), T(0.908), T(0.881), T(0.850), T(0.818),
                               T(0.784), T(0.751), T(0.718), T(0.685), T(0.658), T(0.628), T(0.603), T(0.580), T(0.558),
                               T(0.538), T(0.522), T(0.506), T(0.490), T(0.478), T(0.467), T(0.457), T(0.448), T(0.438),
                               T(0.431), T(0.424), T(0.420), T(0.414), T(0.411), T(0.406)};

 public:
  const char* name() const override { return "Osborne 1"; }
  int m() const override { return 33; }
  int n() const override { return 5; }
  std::vector<double> start() const override { return {0.5, 1.5, -1, 0.01, 0.02}; }
  void residuals(const T* x, T* f) const override {
    using std::exp;
    for (int i = 0; i < 33; ++i) {
      const T t = T(10 * i);
      f[i] = kY[i] - (x[0] + x[1] * exp(-t * x[3]) + x[2] * exp(-t * x[4]));
    }
  }
  void jacobian(const T* x, T* J, int ld) const override {
    using std::exp;
    for (int i = 0; i < 33; ++i) {
      const T t = T(10 * i);
      const T e4 = exp(-t * x[3]);
      const T e5 = exp(-t * x[4]);
      J[i] = T(-1);
      J[i + ld] = -e4;
      J[i + 2 * ld] = -e5;
      J[i + 3 * ld] = t * x[1] * e4;
      J[i + 4 * ld] = t * x[2] * e5;
    }
  }
  double minimum() const override { return 5.46489469748e-5; }
  std::vector<double> minimiser() const override { return {0.3754100, 1.9358469, -1.4646871, 0.0128675, 0.0221227}; }
};

/// MINPACK callbacks (cminpack's and ours have this shape) on a Problem<T> passed as `p`.
template <class T>
int lmder_callback(void* p, int, int, const T* x, T* fvec, T* fjac, int ldfjac, int iflag) {
  const auto* problem = static_cast<const Problem<T>*>(p);
  if (iflag == 1) problem->residuals(x, fvec);
  if (iflag == 2) problem->jacobian(x, fjac, ldfjac);
  return 0;
}
template <class T>
int lmdif_callback(void* p, int, int, const T* x, T* fvec, int iflag) {
  if (iflag != 0) static_cast<const Problem<T>*>(p)->residuals(x, fvec);
  return 0;
}

/// The nine problems the issue names, in MINPACK's order of the MGH paper.
template <class T>
std::vector<std::unique_ptr<Problem<T>>> all_problems() {
  std::vector<std::unique_ptr<Problem<T>>> problems;
  problems.emplace_back(new Rosenbrock<T>);
  problems.emplace_back(new PowellSingular<T>);
  problems.emplace_back(new FreudensteinRoth<T>);
  problems.emplace_back(new Bard<T>);
  problems.emplace_back(new KowalikOsborne<T>);
  problems.emplace_back(new Box3d<T>);
  problems.emplace_back(new JennrichSampson<T>);
  problems.emplace_back(new BrownDennis<T>);
  problems.emplace_back(new Osborne1<T>);
  return problems;
}

}  // namespace mgh
