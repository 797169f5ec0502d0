// hdf5_handles.h — private RAII for HDF5 identifiers and for switching off HDF5's automatic error printing, shared by
// the HDF5 readers and writers of metric/ (sampled_field_hdf5.cpp, spatial_metric_hdf5.cpp). Every failure becomes
// one InputError in the caller's words.
#pragma once

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <hdf5.h>

#include "conformesh/intrinsic/errors.h"

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
  hid_t release() {  // the identifier, no longer closed by this
    const hid_t id = id_;
    id_ = -1;
    return id;
  }
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

// A new HDF5 file for `path`, written under a temporary name in the same folder (`path`.tmp-PID-N) and renamed over
// `path` by commit(), so that no reader sees half a file; destroyed uncommitted (an error on the way), it removes the
// temporary and leaves `path` as it was. target() is the group to write into: the file itself for "/", else `group`,
// created with its intermediate groups. `where` names both in errors ("FILE:/group"). Throws InputError.
class NewFileGroup {
 public:
  NewFileGroup(const std::string& path, const std::string& group)
      : path_(path), temp_(path + ".tmp-" + std::to_string(static_cast<long>(::getpid())) + "-" +
                           std::to_string(counter()++)),
        where(path + (group == "/" ? "" : ":" + group)) {
    file_.emplace(H5Fcreate(temp_.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (!file_->valid()) throw InputError(path + ": cannot create the HDF5 file");
    if (group == "/") return;
    Id lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    H5Pset_create_intermediate_group(lcpl.get(), 1);
    group_.emplace(H5Gcreate2(file_->get(), group.c_str(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    if (!group_->valid()) throw InputError(where + ": cannot create the group");
  }
  NewFileGroup(const NewFileGroup&) = delete;
  NewFileGroup& operator=(const NewFileGroup&) = delete;
  ~NewFileGroup() {
    group_.reset();
    file_.reset();
    if (!committed_) std::remove(temp_.c_str());
  }
  hid_t target() const { return group_ ? group_->get() : file_->get(); }
  // Closes the file (HDF5 flushes it) and renames it into place.
  void commit() {
    group_.reset();
    const herr_t closed = H5Fclose(file_->release());
    file_.reset();
    if (closed < 0) throw InputError(path_ + ": cannot write the HDF5 file");
    if (std::rename(temp_.c_str(), path_.c_str()) != 0)
      throw InputError(path_ + ": cannot replace with the written file: " + std::strerror(errno));
    committed_ = true;
  }

 private:
  static std::atomic<unsigned>& counter() {
    static std::atomic<unsigned> n{0};
    return n;
  }
  std::string path_, temp_;
  std::optional<Id> file_, group_;
  bool committed_ = false;

 public:
  const std::string where;
};

// The names of a group's links (datasets and subgroups), in name order; none if the group cannot be listed.
inline std::vector<std::string> linkNames(hid_t group) {
  std::vector<std::string> names;
  H5G_info_t info;
  if (H5Gget_info(group, &info) < 0) return names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len <= 0) continue;
    std::string s(static_cast<size_t>(len) + 1, '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, s.data(), s.size(), H5P_DEFAULT);
    s.resize(static_cast<size_t>(len));
    names.push_back(s);
  }
  return names;
}

}  // namespace conformesh::intrinsic::hdf5_detail
