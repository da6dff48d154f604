#include <sc/io/CheckpointFile.hpp>

#include <sc/io/AtomicFile.hpp>
#include <sc/io/OutputDirectory.hpp>

#include <sc/core/Error.hpp>

#include <hdf5.h>

#include "sc/io/detail/Hdf5Handles.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <sys/stat.h>

namespace sc::io {

namespace {

using ErrorPrintingOff = detail::Hdf5ErrorPrintingOff;
using Handle = detail::Hdf5Handle;

// Writing: a failure names the file, the object and, for the usual write failures, the system's
// reason (errno may be stale otherwise).
hid_t checkWrite(hid_t id, const std::string& what, const std::string& object,
                 const std::string& file)
{
  if (id < 0) {
    const int err = errno;
    const bool writeError =
        err == ENOSPC || err == EDQUOT || err == EFBIG || err == EIO || err == EROFS;
    SC_THROW_IF(true, sc::core::Error,
                "HDF5 error: " << what << " failed for '" << object << "' in the checkpoint '"
                               << file << "'"
                               << (writeError ? std::string(": ") + std::strerror(err) : ""));
  }
  return id;
}

void writeDataset(hid_t file, const std::string& name, hid_t memType, hid_t fileType, std::size_t n,
                  const void* data, const std::string& path)
{
  const hsize_t dims[1] = {static_cast<hsize_t>(n)};
  Handle space(checkWrite(H5Screate_simple(1, dims, nullptr), "H5Screate_simple", name, path),
               H5Sclose);
  Handle set(checkWrite(H5Dcreate2(file, name.c_str(), fileType, space.get(), H5P_DEFAULT,
                                   H5P_DEFAULT, H5P_DEFAULT),
                        "H5Dcreate2", name, path),
             H5Dclose);
  if (n > 0)
    checkWrite(H5Dwrite(set.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "H5Dwrite", name,
               path);
}

// FNV-1a, 64 bits: each step h = (h ^ byte) · prime is a bijection of h for a given byte, so two
// byte sequences of one length that differ in one byte (a flipped bit) never hash alike.
class Fnv1a {
public:
  void add(const void* data, std::size_t n)
  {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i)
      h_ = (h_ ^ b[i]) * 0x100000001b3ULL;
  }
  void add(const std::string& s)
  {
    const unsigned long long n = s.size();
    add(&n, sizeof n);
    add(s.data(), s.size());
  }
  unsigned long long value() const { return h_; }

private:
  unsigned long long h_ = 0xcbf29ce484222325ULL;
};

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* out)
{
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

}  // namespace

unsigned long long CheckpointFile::checksum() const
{
  // Every entry with its kind, name, length and bytes, in name order within each kind.
  Fnv1a h;
  for (const auto& [name, v] : ints_) {
    h.add("i"), h.add(name);
    const unsigned long long n = v.size();
    h.add(&n, sizeof n);
    h.add(v.data(), v.size() * sizeof(long long));
  }
  for (const auto& [name, v] : doubles_) {
    h.add("d"), h.add(name);
    const unsigned long long n = v.size();
    h.add(&n, sizeof n);
    h.add(v.data(), v.size() * sizeof(double));
  }
  for (const auto& [name, v] : strings_)
    h.add("s"), h.add(name), h.add(v);
  return h.value();
}

void CheckpointFile::setInts(const std::string& name, std::vector<long long> values)
{
  ints_[name] = std::move(values);
}

void CheckpointFile::setDoubles(const std::string& name, std::vector<double> values)
{
  doubles_[name] = std::move(values);
}

void CheckpointFile::setString(const std::string& name, const std::string& value)
{
  strings_[name] = value;
}

bool CheckpointFile::has(const std::string& name) const
{
  return ints_.count(name) || doubles_.count(name) || strings_.count(name);
}

const std::vector<long long>& CheckpointFile::ints(const std::string& name) const
{
  auto it = ints_.find(name);
  SC_THROW_IF(it == ints_.end(), sc::core::InputError,
              "the checkpoint '" << path_ << "' has no integer dataset '" << name
                                 << "' (not a checkpoint of this version, or damaged)");
  return it->second;
}

const std::vector<double>& CheckpointFile::doubles(const std::string& name) const
{
  auto it = doubles_.find(name);
  SC_THROW_IF(it == doubles_.end(), sc::core::InputError,
              "the checkpoint '" << path_ << "' has no double dataset '" << name
                                 << "' (not a checkpoint of this version, or damaged)");
  return it->second;
}

const std::string& CheckpointFile::string(const std::string& name) const
{
  auto it = strings_.find(name);
  SC_THROW_IF(it == strings_.end(), sc::core::InputError,
              "the checkpoint '" << path_ << "' has no string dataset '" << name
                                 << "' (not a checkpoint of this version, or damaged)");
  return it->second;
}

void CheckpointFile::write(const std::string& path) const
{
  // A full disk is found before HDF5 writes anything (as for the fields, docs/reliability.md).
  unsigned long long bytes = 64 * 1024;
  for (const auto& e : ints_)
    bytes += 8 * e.second.size() + 1024;
  for (const auto& e : doubles_)
    bytes += 8 * e.second.size() + 1024;
  for (const auto& e : strings_)
    bytes += e.second.size() + 1024;
  const std::filesystem::path p(path);
  checkRoomForFile(p.has_parent_path() ? p.parent_path().string() : std::string("."), path,
                   bytes + bytes / 20);

  const std::string tmp = temporaryPathFor(path);
  ErrorPrintingOff quiet;
  try {
    errno = 0;
    Handle file(checkWrite(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                           "H5Fcreate", "/", tmp),
                H5Fclose);
    {
      const std::string format = formatName();
      Handle type(checkWrite(H5Tcopy(H5T_C_S1), "H5Tcopy", "format", tmp), H5Tclose);
      checkWrite(H5Tset_size(type.get(), format.size()), "H5Tset_size", "format", tmp);
      Handle space(checkWrite(H5Screate(H5S_SCALAR), "H5Screate", "format", tmp), H5Sclose);
      Handle attr(checkWrite(H5Acreate2(file.get(), "format", type.get(), space.get(), H5P_DEFAULT,
                                        H5P_DEFAULT),
                             "H5Acreate2", "format", tmp),
                  H5Aclose);
      checkWrite(H5Awrite(attr.get(), type.get(), format.data()), "H5Awrite", "format", tmp);
    }
    {
      // The integrity check of read(): a checksum of every dataset (docs/output.md).
      const unsigned long long sum = checksum();
      Handle space(checkWrite(H5Screate(H5S_SCALAR), "H5Screate", "checksum", tmp), H5Sclose);
      Handle attr(checkWrite(H5Acreate2(file.get(), "checksum", H5T_STD_U64LE, space.get(),
                                        H5P_DEFAULT, H5P_DEFAULT),
                             "H5Acreate2", "checksum", tmp),
                  H5Aclose);
      checkWrite(H5Awrite(attr.get(), H5T_NATIVE_ULLONG, &sum), "H5Awrite", "checksum", tmp);
    }
    for (const auto& [name, v] : ints_)
      writeDataset(file.get(), name, H5T_NATIVE_LLONG, H5T_STD_I64LE, v.size(), v.data(), tmp);
    for (const auto& [name, v] : doubles_)
      writeDataset(file.get(), name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, v.size(), v.data(), tmp);
    for (const auto& [name, v] : strings_)
      writeDataset(file.get(), name, H5T_NATIVE_UCHAR, H5T_STD_U8LE, v.size(), v.data(), tmp);
    errno = 0;
    checkWrite(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "H5Fflush", "/", tmp);
    checkWrite(file.close(), "H5Fclose", "/", tmp);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  renameFile(tmp, path);
}

CheckpointFile CheckpointFile::read(const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  SC_THROW_IF(!fs::exists(path, ec), sc::core::InputError,
              "no checkpoint '" << path << "': the directory given to --restart holds no "
                                << "checkpoint.h5 (it is written after every complete cycle) "
                                << "and no file of a run killed in cycle 0: is it the output "
                                << "directory of the run to continue?");
  SC_THROW_IF(fs::is_directory(path, ec), sc::core::InputError,
              "the checkpoint '" << path << "' is a directory, not a file");
  ErrorPrintingOff quiet;
  auto bad = [&](const std::string& why) -> std::string {
    return "the checkpoint '" + path + "' cannot be read: " + why +
           " (damaged or not a checkpoint)";
  };
  SC_THROW_IF(H5Fis_hdf5(path.c_str()) <= 0, sc::core::InputError, bad("not an HDF5 file"));
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  SC_THROW_IF(file.get() < 0, sc::core::InputError, bad("H5Fopen failed"));
  {
    SC_THROW_IF(H5Aexists(file.get(), "format") <= 0, sc::core::InputError,
                bad("no 'format' attribute"));
    Handle attr(H5Aopen(file.get(), "format", H5P_DEFAULT), H5Aclose);
    Handle type(attr.get() >= 0 ? H5Aget_type(attr.get()) : -1, H5Tclose);
    SC_THROW_IF(type.get() < 0 || H5Tget_class(type.get()) != H5T_STRING, sc::core::InputError,
                bad("its 'format' attribute is not a string"));
    std::string format(H5Tget_size(type.get()), '\0');
    SC_THROW_IF(H5Aread(attr.get(), type.get(), format.data()) < 0, sc::core::InputError,
                bad("H5Aread failed for 'format'"));
    SC_THROW_IF(format != formatName(), sc::core::InputError,
                bad("its format is '" + format + "', not '" + formatName() + "'"));
  }
  unsigned long long recorded = 0;
  {
    SC_THROW_IF(H5Aexists(file.get(), "checksum") <= 0, sc::core::InputError,
                bad("no 'checksum' attribute (written by an older version?)"));
    Handle attr(H5Aopen(file.get(), "checksum", H5P_DEFAULT), H5Aclose);
    Handle type(attr.get() >= 0 ? H5Aget_type(attr.get()) : -1, H5Tclose);
    SC_THROW_IF(type.get() < 0 || H5Tget_class(type.get()) != H5T_INTEGER ||
                    H5Tget_size(type.get()) != 8 ||
                    H5Aread(attr.get(), H5T_NATIVE_ULLONG, &recorded) < 0,
                sc::core::InputError, bad("its 'checksum' attribute cannot be read"));
  }
  std::vector<std::string> names;
  SC_THROW_IF(H5Literate(file.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collectName, &names) < 0,
              sc::core::InputError, bad("cannot list its datasets"));
  CheckpointFile cp;
  cp.path_ = path;
  for (const auto& name : names) {
    Handle set(H5Dopen2(file.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
    SC_THROW_IF(set.get() < 0, sc::core::InputError, bad("cannot open dataset '" + name + "'"));
    Handle space(H5Dget_space(set.get()), H5Sclose);
    Handle type(H5Dget_type(set.get()), H5Tclose);
    SC_THROW_IF(space.get() < 0 || type.get() < 0 || H5Sget_simple_extent_ndims(space.get()) != 1,
                sc::core::InputError, bad("dataset '" + name + "' is not a 1-D array"));
    hsize_t n = 0;
    H5Sget_simple_extent_dims(space.get(), &n, nullptr);
    const H5T_class_t cls = H5Tget_class(type.get());
    const std::size_t size = H5Tget_size(type.get());
    herr_t status = 0;
    if (cls == H5T_FLOAT && size == 8) {
      auto& v = cp.doubles_[name];
      v.resize(n);
      if (n > 0)
        status = H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    } else if (cls == H5T_INTEGER && size == 8) {
      auto& v = cp.ints_[name];
      v.resize(n);
      if (n > 0)
        status = H5Dread(set.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    } else if (cls == H5T_INTEGER && size == 1) {
      auto& v = cp.strings_[name];
      v.resize(n);
      if (n > 0)
        status = H5Dread(set.get(), H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    } else {
      SC_THROW_IF(true, sc::core::InputError, bad("dataset '" + name + "' has an unexpected type"));
    }
    SC_THROW_IF(status < 0, sc::core::InputError, bad("H5Dread failed for '" + name + "'"));
  }
  // Before the caller trusts anything (and before a restart removes the killed cycle's files):
  // a changed byte anywhere in the datasets (a flipped bit, an edited coordinate) is refused.
  const unsigned long long computed = cp.checksum();
  if (computed != recorded) {
    std::ostringstream os;
    os << std::hex << "the checkpoint '" << path << "' fails its integrity check: its datasets "
       << "hash to 0x" << computed << ", the file records 0x" << recorded
       << " (damaged or edited since it was written); nothing was changed in its directory. "
       << "Run the deck again (without --restart), or restart from an intact copy";
    SC_THROW_IF(true, sc::core::InputError, os.str());
  }
  return cp;
}

}  // namespace sc::io
