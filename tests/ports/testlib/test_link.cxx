// SPDX-License-Identifier: BSD-3-Clause
// A program linked with testlib but not using it builds and runs (upstream's test_link.cxx).
int main() { return 0; }
