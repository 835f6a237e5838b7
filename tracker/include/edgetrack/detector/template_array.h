// SPDX-License-Identifier: BSD-3-Clause
/// A template set's templates or its features: built on the heap (made, or read from a template
/// file), or read in place from constant data linked into the program (`edgetrack templates
/// --cxx`, template_io.h's constant_template_set), which a firmware keeps in flash: never copied.
#pragma once

#include <cstddef>
#include <vector>

namespace edgetrack {

template <class T>
class TemplateArray {
 public:
  TemplateArray() = default;
  /// The `count` elements at `constant`, read in place; they must outlive every copy.
  static TemplateArray in_place(const T* constant, size_t count) {
    TemplateArray array;
    array.data_ = constant;
    array.size_ = count;
    array.in_place_ = true;
    return array;
  }
  TemplateArray(const TemplateArray& other) : owned_(other.owned_), in_place_(other.in_place_) { point_at(other); }
  TemplateArray(TemplateArray&& other) noexcept : owned_(std::move(other.owned_)), in_place_(other.in_place_) {
    point_at(other);
    other.clear();
  }
  TemplateArray& operator=(const TemplateArray& other) {
    if (this != &other) {
      owned_ = other.owned_;
      in_place_ = other.in_place_;
      point_at(other);
    }
    return *this;
  }
  TemplateArray& operator=(TemplateArray&& other) noexcept {
    if (this != &other) {
      owned_ = std::move(other.owned_);
      in_place_ = other.in_place_;
      point_at(other);
      other.clear();
    }
    return *this;
  }

  /// Appends on the heap (a set read in place is first copied there).
  void push_back(const T& value) {
    if (in_place_) {
      owned_.assign(data_, data_ + size_);
      in_place_ = false;
    }
    owned_.push_back(value);
    data_ = owned_.data();
    size_ = owned_.size();
  }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const T& operator[](size_t i) const { return data_[i]; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  /// Whether the elements are read where they were linked (constant data), not from the heap.
  bool read_in_place() const { return in_place_; }

 private:
  void point_at(const TemplateArray& other) {
    data_ = in_place_ ? other.data_ : owned_.data();
    size_ = other.size_;
  }
  void clear() {
    owned_.clear();
    data_ = nullptr;
    size_ = 0;
    in_place_ = false;
  }
  std::vector<T> owned_;
  const T* data_ = nullptr;
  size_t size_ = 0;
  bool in_place_ = false;
};

}  // namespace edgetrack
