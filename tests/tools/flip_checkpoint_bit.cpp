// flip_checkpoint_bit FILE DATASET BYTE BIT: flips bit BIT (0..7) of byte BYTE of the stored data
// of dataset DATASET in the HDF5 file FILE (contiguous layout, as CheckpointFile writes), in place.
// For the checkpoint integrity test (tests/CheckpointIntegrity.cmake).
#include <hdf5.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

int main(int argc, char** argv)
{
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s FILE DATASET BYTE BIT\n", argv[0]);
    return 2;
  }
  const std::string path = argv[1];
  const long long byte = std::atoll(argv[3]);
  const int bit = std::atoi(argv[4]);
  haddr_t offset = HADDR_UNDEF;
  hsize_t size = 0;
  {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file < 0) return 1;
    const hid_t set = H5Dopen2(file, argv[2], H5P_DEFAULT);
    if (set < 0) return 1;
    offset = H5Dget_offset(set);
    size = H5Dget_storage_size(set);
    H5Dclose(set);
    H5Fclose(file);
  }
  if (offset == HADDR_UNDEF || byte < 0 || static_cast<hsize_t>(byte) >= size || bit < 0 ||
      bit > 7) {
    std::fprintf(stderr, "%s: dataset '%s' has %llu bytes; byte %lld bit %d is not among them\n",
                 argv[0], argv[2], static_cast<unsigned long long>(size), byte, bit);
    return 1;
  }
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(static_cast<std::streamoff>(offset + byte));
  char c = 0;
  f.get(c);
  c = static_cast<char>(c ^ (1 << bit));
  f.seekp(static_cast<std::streamoff>(offset + byte));
  f.put(c);
  return f ? 0 : 1;
}
