#include <sc/mesh/GmshSession.hpp>

#include <gmsh.h>

#include <vector>

namespace sc::mesh {

namespace {
int openSessions = 0;
long long modelsMade = 0;
}  // namespace

GmshSession::GmshSession()
{
  if (openSessions == 0) {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
    gmsh::option::setNumber("General.NumThreads", 1);
  }
  ++openSessions;
  clearErrors();
  model_ = "stresscontact-" + std::to_string(++modelsMade);
  gmsh::model::add(model_);
}

GmshSession::~GmshSession()
{
  try {
    gmsh::model::setCurrent(model_);
    gmsh::model::remove();
  } catch (...) {
  }
  if (--openSessions == 0) {
    try {
      gmsh::logger::stop();
      gmsh::finalize();
    } catch (...) {
    }
  }
}

void GmshSession::activate() const { gmsh::model::setCurrent(model_); }

void GmshSession::clearErrors()
{
  // Stopping the logger discards what it kept; the messages of the next operation start afresh.
  try {
    gmsh::logger::stop();
  } catch (...) {
  }
  gmsh::logger::start();
}

namespace {
std::string lastErrorOrEmpty()
{
  std::vector<std::string> log;
  try {
    gmsh::logger::get(log);
  } catch (...) {
    return {};
  }
  const std::string tag = "Error: ";
  for (auto it = log.rbegin(); it != log.rend(); ++it)
    if (it->compare(0, tag.size(), tag) == 0) return it->substr(tag.size());
  return {};
}
}  // namespace

bool GmshSession::hasError() { return !lastErrorOrEmpty().empty(); }

std::string GmshSession::lastError()
{
  const std::string e = lastErrorOrEmpty();
  return e.empty() ? std::string("(Gmsh gave no message)") : e;
}

}  // namespace sc::mesh
