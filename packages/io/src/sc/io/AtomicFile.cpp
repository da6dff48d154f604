#include <sc/io/AtomicFile.hpp>

#include <sc/core/Error.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace sc::io {

std::string temporaryPathFor(const std::string& path, long processId)
{
  return path + ".tmp." + std::to_string(processId);
}

std::string temporaryPathFor(const std::string& path)
{
  return temporaryPathFor(path, static_cast<long>(::getpid()));
}

void renameFile(const std::string& from, const std::string& to)
{
  if (std::rename(from.c_str(), to.c_str()) != 0) {
    const int err = errno;
    SC_THROW_IF(true, sc::core::Error,
                "Cannot rename '" << from << "' to '" << to << "': " << std::strerror(err));
  }
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), tmpPath_(temporaryPathFor(path_))
{
  out_.open(tmpPath_, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!out_) {
    const int err = errno;
    SC_THROW_IF(true, sc::core::Error,
                "Cannot open '" << tmpPath_ << "' for writing (temporary for '" << path_
                                << "'): " << std::strerror(err));
  }
}

AtomicFile::~AtomicFile()
{
  if (!committed_) {
    out_.close();
    std::remove(tmpPath_.c_str());  // best effort: never leave a stray temporary behind
  }
}

void AtomicFile::commit()
{
  SC_THROW_IF(committed_, sc::core::InternalError, "AtomicFile '" << path_ << "' committed twice");
  out_.flush();
  const bool writeOk = static_cast<bool>(out_);
  out_.close();
  // A full disk shows up here (flush/close), not at the first <<: check before renaming, so a
  // short file never replaces a good one.
  SC_THROW_IF(!writeOk || out_.fail(), sc::core::Error,
              "Writing '" << tmpPath_ << "' (temporary for '" << path_ << "') failed");
  renameFile(tmpPath_, path_);
  committed_ = true;
}

void writeFileAtomically(const std::string& path, const std::string& content)
{
  AtomicFile file(path);
  file.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  file.commit();
}

}  // namespace sc::io
