// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_real_npolynomial.h"

#include <cassert>
#include <cmath>
#include <ostream>
#include <sstream>
#include <utility>

inline namespace edgetrack_ports {

vnl_real_npolynomial::vnl_real_npolynomial(vnl_vector<double> c, const vnl_matrix<unsigned int>& p)
    : coeffs_(std::move(c)), polyn_(p) {
  assert(coeffs_.size() == polyn_.rows());
  simplify();
}

void vnl_real_npolynomial::set(const vnl_vector<double>& c, const vnl_matrix<unsigned int>& p) {
  assert(c.size() == p.rows());
  coeffs_ = c;
  polyn_ = p;
  simplify();
}

double vnl_real_npolynomial::eval(const vnl_vector<double>& x) const {
  assert(x.size() == nvar());
  double total = 0;
  for (unsigned i = 0; i < nterms(); ++i) {
    double term = coeffs_[i];
    for (unsigned j = 0; j < nvar(); ++j) term *= std::pow(x[j], static_cast<int>(polyn_(i, j)));
    total += term;
  }
  return total;
}

double vnl_real_npolynomial::eval(const vnl_matrix<double>& xn) const {
  double total = 0;
  for (unsigned i = 0; i < nterms(); ++i) {
    double term = coeffs_[i];
    for (unsigned j = 0; j < nvar(); ++j) term *= xn(j, polyn_(i, j));
    total += term;
  }
  return total;
}

vnl_real_npolynomial vnl_real_npolynomial::deriv(unsigned int v) const {
  assert(v < nvar());
  vnl_vector<double> c(coeffs_);
  vnl_matrix<unsigned int> p(polyn_);
  for (unsigned i = 0; i < nterms(); ++i) {
    c[i] *= p(i, v);  // a term without x_v becomes zero and simplify() drops it
    if (p(i, v) > 0) --p(i, v);
  }
  return vnl_real_npolynomial(c, p);
}

double vnl_real_npolynomial::deval(const vnl_vector<double>& x, unsigned int i) const { return deriv(i).eval(x); }

vnl_vector<double> vnl_real_npolynomial::deval(const vnl_vector<double>& x) const {
  vnl_vector<double> gradient(nvar());
  for (unsigned i = 0; i < nvar(); ++i) gradient[i] = deval(x, i);
  return gradient;
}

vnl_real_npolynomial vnl_real_npolynomial::operator-() const { return *this * -1.0; }

vnl_real_npolynomial vnl_real_npolynomial::operator+(const vnl_real_npolynomial& rhs) const {
  if (nterms() == 0) return rhs;
  if (rhs.nterms() == 0) return *this;
  assert(nvar() == rhs.nvar());
  vnl_vector<double> c(nterms() + rhs.nterms());
  vnl_matrix<unsigned int> p(c.size(), nvar());
  c.update(coeffs_, 0);
  c.update(rhs.coeffs_, nterms());
  p.update(polyn_, 0, 0);
  p.update(rhs.polyn_, nterms(), 0);
  return vnl_real_npolynomial(c, p);
}

vnl_real_npolynomial vnl_real_npolynomial::operator*(const vnl_real_npolynomial& rhs) const {
  if (nterms() == 0 || rhs.nterms() == 0) return vnl_real_npolynomial();
  assert(nvar() == rhs.nvar());
  vnl_vector<double> c(nterms() * rhs.nterms());
  vnl_matrix<unsigned int> p(c.size(), nvar());
  for (unsigned i = 0, k = 0; i < nterms(); ++i) {
    for (unsigned j = 0; j < rhs.nterms(); ++j, ++k) {
      c[k] = coeffs_[i] * rhs.coeffs_[j];
      for (unsigned v = 0; v < nvar(); ++v) p(k, v) = polyn_(i, v) + rhs.polyn_(j, v);
    }
  }
  return vnl_real_npolynomial(c, p);
}

vnl_real_npolynomial vnl_real_npolynomial::operator+(double c) const {
  vnl_vector<double> constant(1, c);
  return *this + vnl_real_npolynomial(constant, vnl_matrix<unsigned int>(1, nvar(), 0u));
}

vnl_real_npolynomial vnl_real_npolynomial::operator*(double c) const {
  return vnl_real_npolynomial(coeffs_ * c, polyn_);
}

unsigned int vnl_real_npolynomial::degree() const {
  unsigned int best = 0;
  for (unsigned i = 0; i < nterms(); ++i) {
    unsigned int total = 0;
    for (unsigned v = 0; v < nvar(); ++v) total += polyn_(i, v);
    if (total > best) best = total;
  }
  return best;
}

std::vector<unsigned int> vnl_real_npolynomial::degrees() const {
  std::vector<unsigned int> result(nvar(), 0);
  for (unsigned i = 0; i < nterms(); ++i) {
    for (unsigned v = 0; v < nvar(); ++v) {
      if (polyn_(i, v) > result[v]) result[v] = polyn_(i, v);
    }
  }
  return result;
}

unsigned int vnl_real_npolynomial::maxdegree() const {
  unsigned int best = 0;
  for (unsigned int d : degrees()) best = d > best ? d : best;
  return best;
}

void vnl_real_npolynomial::simplify() {
  std::vector<double> c;
  std::vector<std::vector<unsigned>> p;
  for (unsigned i = 0; i < coeffs_.size(); ++i) {
    std::vector<unsigned> exponents(polyn_.cols());
    for (unsigned v = 0; v < polyn_.cols(); ++v) exponents[v] = polyn_(i, v);
    std::size_t k = 0;
    while (k < p.size() && p[k] != exponents) ++k;
    if (k == p.size()) {
      p.push_back(exponents);
      c.push_back(0.0);
    }
    c[k] += coeffs_[i];
  }
  const std::size_t cols = polyn_.cols();
  coeffs_.set_size(0);
  vnl_vector<double> kept_c(c.size());
  vnl_matrix<unsigned int> kept_p(c.size(), cols);
  unsigned kept = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (c[k] == 0.0) continue;
    kept_c[kept] = c[k];
    for (std::size_t v = 0; v < cols; ++v) kept_p(kept, v) = p[k][v];
    ++kept;
  }
  coeffs_ = kept_c.extract(kept);
  polyn_ = kept_p.extract(kept, cols);
}

std::string vnl_real_npolynomial::asString() const {
  std::ostringstream os;
  for (unsigned i = 0; i < nterms(); ++i) {
    const double c = coeffs_[i];
    if (i > 0) os << (c < 0 ? " - " : " + ");
    if (i == 0 && c < 0) os << '-';
    const double magnitude = std::fabs(c);
    bool has_variable = false;
    std::ostringstream vars;
    for (unsigned v = 0; v < nvar(); ++v) {
      const unsigned e = polyn_(i, v);
      if (e == 0) continue;
      if (has_variable) vars << ' ';
      if (nvar() <= 3) {
        vars << "XYZ"[v];
      } else {
        vars << 'X' << v + 1;
      }
      if (e > 1) vars << '^' << e;
      has_variable = true;
    }
    if (magnitude != 1.0 || !has_variable) os << magnitude << (has_variable ? " " : "");
    os << vars.str();
  }
  if (nterms() == 0) os << '0';
  return os.str();
}

std::ostream& operator<<(std::ostream& os, const vnl_real_npolynomial& p) { return os << p.asString(); }

}  // inline namespace edgetrack_ports
