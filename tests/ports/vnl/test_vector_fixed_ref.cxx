// SPDX-License-Identifier: BSD-3-Clause
// vnl_vector_fixed_ref as upstream's test_vector_fixed_ref.cxx: a view reads and writes the
// memory it is given, assignment copies into that memory, and the const view reads only.
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_vector_fixed_ref.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckFixedRef {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    T storage[4] = {T(1), T(2), T(3), T(4)};
    const vnl_vector_fixed_ref<T, 4> ref(storage);
    TEST("the view reads the memory" + in, ref[2] == T(3), true);
    ref[0] = T(10);
    TEST("writing through the view changes the memory" + in, storage[0] == T(10), true);
    ref.put(1, T(-2));
    TEST("put writes through" + in, storage[1] == T(-2), true);
    vnl_vector_fixed<T, 4> value(T(5));
    ref = value;
    TEST("assignment copies into the memory" + in, storage[3] == T(5), true);
    ref *= T(2);
    TEST("*= scales the memory" + in, storage[2] == T(10), true);
    ref.fill(T(1)).flip();
    TEST("fill then flip" + in, storage[0] == T(1) && ref.sum() == T(4), true);
    vnl_vector_fixed<T, 4> owner(T(0));
    vnl_vector_fixed_ref<T, 4> of_owner(owner);
    of_owner[3] = T(7);
    TEST("a view of a vnl_vector_fixed writes into it" + in, owner[3] == T(7), true);
    const vnl_vector_fixed_ref_const<T, 4> cref(owner);
    TEST("const view reads" + in, cref[3] == T(7) && cref.max_value() == T(7) && cref.arg_max() == 3u, true);
    TEST_NEAR("const view two_norm" + in, cref.two_norm(), 7.0, ulps<T>(8));
    TEST("as_vector copies" + in, cref.as_vector()[3] == T(7), true);
    TEST("sum of two views" + in, (cref + ref)[3] == T(8), true);
    TEST("dot product of views" + in, dot_product(cref, vnl_vector_fixed_ref_const<T, 4>(ref)) == T(7), true);
  }
};

void test_vector_fixed_ref() { for_each_test_scalar<CheckFixedRef>(); }

}  // namespace

TESTMAIN(test_vector_fixed_ref)
