#pragma once
// Internal to the io package (XdmfWriter.cpp, CheckpointFile.cpp): RAII helpers for the HDF5 C API.
#include <hdf5.h>

namespace sc::io::detail {

// Turns HDF5's automatic error-stack printing off while we work (we report errors ourselves,
// naming file and dataset) and restores the caller's setting afterwards.
class Hdf5ErrorPrintingOff {
public:
  Hdf5ErrorPrintingOff()
  {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~Hdf5ErrorPrintingOff() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  Hdf5ErrorPrintingOff(const Hdf5ErrorPrintingOff&) = delete;
  Hdf5ErrorPrintingOff& operator=(const Hdf5ErrorPrintingOff&) = delete;

private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// Owns an HDF5 identifier and closes it with the matching H5?close.
class Hdf5Handle {
public:
  Hdf5Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Hdf5Handle()
  {
    if (id_ >= 0) close_(id_);
  }
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  hid_t get() const { return id_; }
  // Close now and report failure (used for files, where close flushes the data).
  herr_t close()
  {
    const herr_t status = id_ >= 0 ? close_(id_) : 0;
    id_ = -1;
    return status;
  }

private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

}  // namespace sc::io::detail
