// hdf5_handles.h — private RAII for HDF5 identifiers and for switching off HDF5's automatic error printing, shared by
// the HDF5 readers of metric/ (sampled_field_hdf5.cpp, spatial_metric_hdf5.cpp). Every failure becomes one InputError in the caller's words.
#pragma once

#include <fstream>
#include <string>
#include <utility>

#include <hdf5.h>

namespace conformesh::intrinsic::hdf5_detail {

class Id {
 public:
  using Closer = herr_t (*)(hid_t);
  Id(hid_t id, Closer close) : id_(id), close_(close) {}
  Id(Id&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  Id& operator=(Id&&) = delete;
  ~Id() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  Closer close_;
};

class QuietErrors {
 public:
  QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;
  ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// Splits "FILE:/group" when FILE exists and the whole string does not; else (whole, "/").
inline std::pair<std::string, std::string> splitGroup(const std::string& s) {
  if (std::ifstream(s)) return {s, "/"};
  const size_t colon = s.rfind(':');
  if (colon != std::string::npos && colon + 1 < s.size() && s[colon + 1] == '/')
    return {s.substr(0, colon), s.substr(colon + 1)};
  return {s, "/"};
}

}  // namespace conformesh::intrinsic::hdf5_detail
