// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_amoeba.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "vnl/vnl_cost_function.h"
#include "vnl/vnl_least_squares_function.h"

inline namespace edgetrack_ports {

namespace {

using Simplex = std::vector<vnl_amoeba_SimplexCorner>;

/// One Nelder-Mead run over a simplex of n + 1 corners, counting evaluations.
class SimplexSearch {
 public:
  SimplexSearch(vnl_cost_function& f, const vnl_amoeba& settings) : f_(f), settings_(settings) {}

  void set_corner(vnl_amoeba_SimplexCorner& corner, const vnl_vector<double>& v) {
    corner.v = v;
    corner.fv = f_.f(v);
    ++evaluations_;
  }
  /// corner = (1 - lambda) from + lambda to: lambda -1 reflects `to` through `from`, 2 doubles
  /// that, 1/2 halves the way.
  void set_corner_between(vnl_amoeba_SimplexCorner& corner, const vnl_vector<double>& from,
                          const vnl_vector<double>& to, double lambda) {
    set_corner(corner, (1 - lambda) * from + lambda * to);
  }

  Simplex relative_start(const vnl_vector<double>& x) {
    Simplex simplex(x.size() + 1);
    set_corner(simplex[0], x);
    for (unsigned j = 0; j < x.size(); ++j) {
      vnl_vector<double> v = x;
      v[j] = std::fabs(v[j]) > settings_.zero_term_delta ? (1 + settings_.relative_diameter) * v[j]
                                                         : settings_.zero_term_delta;
      set_corner(simplex[j + 1], v);
    }
    return simplex;
  }

  Simplex absolute_start(const vnl_vector<double>& x, const vnl_vector<double>& dx) {
    Simplex simplex(x.size() + 1);
    set_corner(simplex[0], x);
    for (unsigned j = 0; j < x.size(); ++j) {
      vnl_vector<double> v = x;
      v[j] += dx[j];
      set_corner(simplex[j + 1], v);
    }
    return simplex;
  }

  /// Runs until converged or out of evaluations; x becomes the best corner.
  void run(Simplex& simplex, vnl_vector<double>& x) {
    const unsigned n = x.size();
    sort(simplex);
    vnl_amoeba_SimplexCorner reflect(n), expand(n), contract(n), shrink(n);
    vnl_vector<double> centroid(n);
    while (evaluations_ < settings_.maxiter && !converged(simplex)) {
      centroid.fill(0);
      for (unsigned i = 0; i < n; ++i) centroid += simplex[i].v;  // all but the worst corner
      centroid /= double(n);
      const char* how = "reflect";
      set_corner_between(reflect, centroid, simplex[n].v, -1);
      const vnl_amoeba_SimplexCorner* next = &reflect;
      if (reflect.fv < simplex[n - 1].fv) {
        if (reflect.fv < simplex[0].fv) {
          set_corner_between(expand, centroid, reflect.v, 2);
          if (expand.fv < simplex[0].fv) next = &expand, how = "expand";
        }
      } else {
        // Contract towards the better of the worst corner and its reflection.
        const vnl_amoeba_SimplexCorner& toward = reflect.fv < simplex[n].fv ? reflect : simplex[n];
        set_corner_between(contract, centroid, toward.v, 0.5);
        if (contract.fv < simplex[0].fv) {
          next = &contract, how = "contract";
        } else {
          for (unsigned j = 1; j < n; ++j) set_corner_between(simplex[j], simplex[0].v, simplex[j].v, 0.5);
          set_corner_between(shrink, simplex[0].v, simplex[n].v, 0.5);
          next = &shrink, how = "shrink";
        }
      }
      simplex[n] = *next;
      sort(simplex);
      if (settings_.verbose) std::cerr << "iter " << evaluations_ << ": " << how << ' ' << simplex[0].fv << '\n';
    }
    x = simplex[0].v;
    end_error_ = simplex[0].fv;
  }

  int evaluations() const { return evaluations_; }
  double end_error() const { return end_error_; }

 private:
  static void sort(Simplex& simplex) {
    std::stable_sort(simplex.begin(), simplex.end(),
                     [](const vnl_amoeba_SimplexCorner& a, const vnl_amoeba_SimplexCorner& b) { return a.fv < b.fv; });
  }
  /// Largest coordinate step between consecutive sorted corners, and the spread of the values.
  bool converged(const Simplex& simplex) const {
    double diameter = 0;
    for (size_t i = 0; i + 1 < simplex.size(); ++i) {
      for (unsigned k = 0; k < simplex[i].v.size(); ++k)
        diameter = std::max(diameter, std::fabs(simplex[i].v[k] - simplex[i + 1].v[k]));
    }
    return diameter < settings_.X_tolerance && simplex.back().fv - simplex.front().fv < settings_.F_tolerance;
  }

  vnl_cost_function& f_;
  const vnl_amoeba& settings_;
  int evaluations_ = 0;
  double end_error_ = 0;
};

/// The sum of squared residuals of a least-squares function, as a cost.
class SumOfSquares : public vnl_cost_function {
 public:
  explicit SumOfSquares(vnl_least_squares_function& ls)
      : vnl_cost_function(static_cast<int>(ls.get_number_of_unknowns())), ls_(ls), fx_(ls.get_number_of_residuals()) {}
  double f(const vnl_vector<double>& x) override {
    ls_.f(x, fx_);
    return fx_.squared_magnitude();
  }

 private:
  vnl_least_squares_function& ls_;
  vnl_vector<double> fx_;
};

}  // namespace

vnl_amoeba::vnl_amoeba(vnl_cost_function& f) : maxiter(f.get_number_of_unknowns() * 200), fptr(&f) {}

void vnl_amoeba::minimize(vnl_vector<double>& x) {
  SimplexSearch search(*fptr, *this);
  Simplex simplex = search.relative_start(x);
  search.run(simplex, x);
  num_evaluations_ = search.evaluations();
  end_error_ = search.end_error();
}

void vnl_amoeba::minimize(vnl_vector<double>& x, const vnl_vector<double>& dx) {
  SimplexSearch search(*fptr, *this);
  Simplex simplex = search.absolute_start(x, dx);
  search.run(simplex, x);
  num_evaluations_ = search.evaluations();
  end_error_ = search.end_error();
}

void vnl_amoeba::minimize(vnl_cost_function& f, vnl_vector<double>& x) { minimize(f, x, 0.0); }

void vnl_amoeba::minimize(vnl_cost_function& f, vnl_vector<double>& x, double delta) {
  vnl_amoeba a(f);
  if (delta != 0) a.relative_diameter = delta;
  a.minimize(x);
}

void vnl_amoeba::minimize(vnl_cost_function& f, vnl_vector<double>& x, const vnl_vector<double>& dx) {
  vnl_amoeba a(f);
  a.minimize(x, dx);
}

void vnl_amoeba::minimize(vnl_least_squares_function& f, vnl_vector<double>& x) {
  SumOfSquares cost(f);
  minimize(cost, x);
}

}  // inline namespace edgetrack_ports
