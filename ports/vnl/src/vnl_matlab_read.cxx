// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_matlab_read.h"

#include <cstdlib>
#include <cstring>
#include <type_traits>
#include <vector>

inline namespace edgetrack_ports {

namespace {
constexpr bool kBigEndianHost = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;

/// A type code this reader knows: byte order 0/1000 + storage 0/100 + precision 0/10.
bool is_known_type(std::int32_t type) {
  const std::int32_t rest = type % 1000;
  return type >= 0 && type < 2000 && (rest == 0 || rest == 10 || rest == 100 || rest == 110);
}

template <class R>
void swap_bytes(R& x) {
  if constexpr (sizeof(R) == 4) {
    byteswap::swap32(&x);
  } else {
    byteswap::swap64(&x);
  }
}

template <class T>
struct parts {  // float, double
  using real_type = T;
  static constexpr bool is_complex = false;
};
template <class T>
struct parts<std::complex<T>> {
  using real_type = T;
  static constexpr bool is_complex = true;
};
}  // namespace

template <class T>
void vnl_matlab_read_data(std::istream& s, T* ptr, unsigned n) {
  using R = typename parts<T>::real_type;
  std::vector<R> re(n), im(parts<T>::is_complex ? n : 0);
  s.read(reinterpret_cast<char*>(re.data()), static_cast<std::streamsize>(n * sizeof(R)));
  if constexpr (parts<T>::is_complex) {
    s.read(reinterpret_cast<char*>(im.data()), static_cast<std::streamsize>(n * sizeof(R)));
    for (unsigned i = 0; i < n; ++i) ptr[i] = T(re[i], im[i]);
  } else {
    for (unsigned i = 0; i < n; ++i) ptr[i] = re[i];
  }
}

vnl_matlab_readhdr::vnl_matlab_readhdr(std::istream& s) : s_(s) { read_hdr(); }

void vnl_matlab_readhdr::read_hdr() {
  hdr_ = vnl_matlab_header{};
  s_.read(reinterpret_cast<char*>(&hdr_), sizeof hdr_);
  // Native when the code is known and says this machine's order; else the file is swapped.
  need_swap_ = !(is_known_type(hdr_.type) && ((hdr_.type >= vnl_matlab_header::vnl_BIG_ENDIAN) == kBigEndianHost));
  if (need_swap_) {
    for (std::int32_t* field : {&hdr_.type, &hdr_.rows, &hdr_.cols, &hdr_.imag, &hdr_.namlen}) byteswap::swap32(field);
  }
  name_.clear();
  if (s_ && hdr_.namlen > 0 && hdr_.namlen < (1 << 20)) {
    std::vector<char> name(static_cast<std::size_t>(hdr_.namlen));
    s_.read(name.data(), hdr_.namlen);
    name_.assign(name.data(), strnlen(name.data(), name.size()));
  }
  data_read_ = false;
}

void vnl_matlab_readhdr::read_next() {
  if (!data_read_) {
    std::streamsize bytes = static_cast<std::streamsize>(rows()) * cols() * (is_single() ? 4 : 8);
    if (is_complex()) bytes *= 2;
    s_.ignore(bytes);
  }
  read_hdr();
}

template <class T>
bool vnl_matlab_readhdr::stores() {
  using R = typename parts<T>::real_type;
  return is_single() == std::is_same<R, float>::value && is_complex() == parts<T>::is_complex;
}

template <class T>
bool vnl_matlab_readhdr::read_values(T* p, long n) {
  vnl_matlab_read_data(s_, p, static_cast<unsigned>(n));
  if (need_swap_) {
    using R = typename parts<T>::real_type;
    for (long i = 0; i < n; ++i) {  // each real and imaginary part on its own
      R* components = reinterpret_cast<R*>(p + i);
      for (unsigned c = 0; c < sizeof(T) / sizeof(R); ++c) swap_bytes(components[c]);
    }
  }
  data_read_ = true;
  return bool(*this);
}

template <class T>
bool vnl_matlab_readhdr::read_matrix(T* const* m) {
  if (!stores<T>()) return false;
  std::vector<T> values(static_cast<std::size_t>(rows() * cols()));
  if (!read_values(values.data(), rows() * cols())) return false;
  const long row_step = is_rowwise() ? cols() : 1, col_step = is_rowwise() ? 1 : rows();
  for (long i = 0; i < rows(); ++i) {
    for (long j = 0; j < cols(); ++j) m[i][j] = values[static_cast<std::size_t>(row_step * i + col_step * j)];
  }
  return true;
}

#define VNL_MATLAB_READHDR_METHODS(T)                                                                                  \
  bool vnl_matlab_readhdr::read_data(T& v) { return stores<T>() && rows() == 1 && cols() == 1 && read_values(&v, 1); } \
  bool vnl_matlab_readhdr::read_data(T* p) {                                                                           \
    return stores<T>() && (rows() == 1 || cols() == 1) && read_values(p, rows() * cols());                             \
  }                                                                                                                    \
  bool vnl_matlab_readhdr::read_data(T* const* m) { return read_matrix(m); }
VNL_MATLAB_READHDR_METHODS(float)
VNL_MATLAB_READHDR_METHODS(double)
VNL_MATLAB_READHDR_METHODS(std::complex<float>)
VNL_MATLAB_READHDR_METHODS(std::complex<double>)
#undef VNL_MATLAB_READHDR_METHODS

template <class T>
bool vnl_matlab_read_or_die(std::istream& s, vnl_vector<T>& v, const char* name) {
  vnl_matlab_readhdr h(s);
  if (!s) return false;  // no more data
  if (name && *name && std::strcmp(name, h.name()) != 0) std::abort();
  v.set_size(static_cast<std::size_t>(h.rows() * h.cols()));
  if (!h.read_data(v.data_block())) std::abort();
  return true;
}

template <class T>
bool vnl_matlab_read_or_die(std::istream& s, vnl_matrix<T>& M, const char* name) {
  vnl_matlab_readhdr h(s);
  if (!s) return false;
  if (name && *name && std::strcmp(name, h.name()) != 0) std::abort();
  M.set_size(static_cast<std::size_t>(h.rows()), static_cast<std::size_t>(h.cols()));
  if (!h.read_data(M.data_array())) std::abort();
  return true;
}

#define VNL_MATLAB_READ_INSTANTIATE(T)                                              \
  template void vnl_matlab_read_data(std::istream&, T*, unsigned);                  \
  template bool vnl_matlab_read_or_die(std::istream&, vnl_vector<T>&, const char*); \
  template bool vnl_matlab_read_or_die(std::istream&, vnl_matrix<T>&, const char*)
VNL_MATLAB_READ_INSTANTIATE(float);
VNL_MATLAB_READ_INSTANTIATE(double);
VNL_MATLAB_READ_INSTANTIATE(std::complex<float>);
VNL_MATLAB_READ_INSTANTIATE(std::complex<double>);

}  // inline namespace edgetrack_ports
