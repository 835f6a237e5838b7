// SPDX-License-Identifier: BSD-3-Clause
/// Micro-benchmark: guest instructions per +, *, /, sqrt, sin, cos, atan2, asin, exp and log for
/// double and float (soft-float on the PXA270) and for S47.16 and S40.23 fixed point. Each operation on each seeded operand
/// pair runs inside its own count window; a copy "operation" per type measures what the window
/// holds besides the operation. Run it under toolchains/qemu/count-insns.sh --windows: stdout names
/// the windows in order ("windows <type> <op> <count>": the next <count> windows), results.sh pairs
/// them with the counts. Natively it only computes, which keeps it buildable and checkable.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "count_markers.h"
#include "real/fixed64.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

/// xorshift64*: the same operands on every platform and compiler.
class SeededValues {
 public:
  explicit SeededValues(std::uint64_t seed) : state_(seed) {}
  /// A value in [lo, hi).
  double uniform(double lo, double hi) {
    state_ ^= state_ >> 12;
    state_ ^= state_ << 25;
    state_ ^= state_ >> 27;
    const std::uint64_t bits = (state_ * 0x2545F4914F6CDD1DULL) >> 11;  // 53 random bits
    return lo + (hi - lo) * (static_cast<double>(bits) / 9007199254740992.0);
  }

 private:
  std::uint64_t state_;
};

/// The operands of one operation, as doubles; each type converts them before counting starts.
struct OperandSet {
  std::vector<double> a;
  std::vector<double> b;
};

OperandSet make_operands(std::uint64_t seed, int count, double a_lo, double a_hi, double b_lo, double b_hi,
                         bool random_b_sign) {
  SeededValues values(seed);
  OperandSet set{std::vector<double>(count), std::vector<double>(count)};
  for (int i = 0; i < count; ++i) {
    set.a[i] = values.uniform(a_lo, a_hi);
    const double b = values.uniform(b_lo, b_hi);
    set.b[i] = random_b_sign && values.uniform(0.0, 1.0) < 0.5 ? -b : b;
  }
  return set;
}


/// Makes the compiler treat `value` as read and rewritten here, so the computation that uses it
/// cannot start before this point, and the one that produces it cannot finish after it.
template <class T>
void pin(T& value) {
  __asm__ volatile("" : "+m"(value));
}

/// Applies op to every operand pair, each inside its own count window, and adds the results to
/// a checksum, so the compiler must compute them.
template <class T, class Op>
double count_op(const char* type, const char* op_name, const OperandSet& operands, Op op) {
  const std::size_t n = operands.a.size();
  std::vector<T> a(n);
  std::vector<T> b(n);
  std::vector<T> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = T(operands.a[i]);
    b[i] = T(operands.b[i]);
  }
  std::printf("windows %s %s %zu\n", type, op_name, n);
  for (std::size_t i = 0; i < n; ++i) {
    edgetrack_count_begin();
    T x = a[i];
    T y = b[i];
    pin(x);
    pin(y);
    T result = op(x, y);
    pin(result);
    out[i] = result;
    edgetrack_count_end();
  }
  double sum = 0.0;
  for (const T& x : out) sum += static_cast<double>(x);
  return sum;
}

struct AllOperands {
  OperandSet copy;
  OperandSet add;
  OperandSet mul;
  OperandSet div;
  OperandSet sqrt;
  OperandSet sin;
  OperandSet cos;
  OperandSet atan2;
  OperandSet asin;
  OperandSet exp;
  OperandSet log;
};

template <class T>
double count_type(const char* type, const AllOperands& operands) {
  double checksum = 0.0;
  checksum += count_op<T>(type, "copy", operands.copy, [](T x, T) { return x; });
  checksum += count_op<T>(type, "add", operands.add, [](T x, T y) { return x + y; });
  checksum += count_op<T>(type, "mul", operands.mul, [](T x, T y) { return x * y; });
  checksum += count_op<T>(type, "div", operands.div, [](T x, T y) { return x / y; });
  checksum += count_op<T>(type, "sqrt", operands.sqrt, [](T x, T) {
    using std::sqrt;  // std:: for double and float, fixedpoint:: by argument-dependent lookup
    return sqrt(x);
  });
  checksum += count_op<T>(type, "sin", operands.sin, [](T x, T) {
    using std::sin;
    return sin(x);
  });
  checksum += count_op<T>(type, "cos", operands.cos, [](T x, T) {
    using std::cos;
    return cos(x);
  });
  checksum += count_op<T>(type, "atan2", operands.atan2, [](T y, T x) {
    using std::atan2;
    return atan2(y, x);
  });
  checksum += count_op<T>(type, "asin", operands.asin, [](T x, T) {
    using std::asin;
    return asin(x);
  });
  checksum += count_op<T>(type, "exp", operands.exp, [](T x, T) {
    using std::exp;
    return exp(x);
  });
  checksum += count_op<T>(type, "log", operands.log, [](T x, T) {
    using std::log;
    return log(x);
  });
  std::printf("checksum %s %.6g\n", type, checksum);
  return checksum;
}

}  // namespace

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 1000;
  if (count <= 0) {
    std::fprintf(stderr, "usage: real_ops [operands per op, default 1000]\n");
    return 2;
  }
  AllOperands operands;
  operands.copy = make_operands(1, count, -100.0, 100.0, -100.0, 100.0, false);
  operands.add = make_operands(2, count, -100.0, 100.0, -100.0, 100.0, false);
  operands.mul = make_operands(3, count, -100.0, 100.0, -100.0, 100.0, false);
  operands.div = make_operands(4, count, -100.0, 100.0, 0.5, 100.0, true);
  operands.sqrt = make_operands(5, count, 0.0, 1000.0, 0.0, 1.0, false);
  operands.sin = make_operands(6, count, -kPi, kPi, 0.0, 1.0, false);
  operands.cos = make_operands(7, count, -kPi, kPi, 0.0, 1.0, false);
  operands.atan2 = make_operands(8, count, -100.0, 100.0, -100.0, 100.0, false);
  operands.asin = make_operands(9, count, -1.0, 1.0, 0.0, 1.0, false);
  operands.exp = make_operands(10, count, -10.0, 10.0, 0.0, 1.0, false);
  operands.log = make_operands(11, count, 0.001, 1000.0, 0.0, 1.0, false);

  fixedpoint::reset_saturation_count();
  count_type<double>("double", operands);
  count_type<float>("float", operands);
  count_type<fixedpoint::s47_16>("s47_16", operands);
  count_type<fixedpoint::s40_23>("s40_23", operands);
  // None of these operands is out of range, so a saturation would mean a wrong result.
  std::printf("saturations %llu\n", static_cast<unsigned long long>(fixedpoint::saturation_count()));
  return fixedpoint::saturation_count() == 0 ? 0 : 1;
}
