#pragma once
// Gmsh's library keeps global state. A GmshSession gives its owner a Gmsh model of its own: the
// library is initialised (quietly, without reading ~/.gmshrc) when the first session opens and
// finalised when the last one closes, and every session adds a uniquely named model that it
// removes when it closes. Sessions nest: a CadGeometry keeps its model for the whole run while
// a file is read in a session of its own. Gmsh is not thread-safe: use sessions from one thread.

#include <string>

namespace sc::mesh {

class GmshSession {
public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /// Make this session's model Gmsh's current one (every gmsh:: call acts on the current model).
  void activate() const;
  /// The name of this session's model.
  const std::string& model() const { return model_; }
  /// Gmsh's last error message since this session opened (or since the last clearErrors()), or
  /// "(Gmsh gave no message)".
  static std::string lastError();
  /// True if Gmsh reported an error since the session opened or the last clearErrors().
  static bool hasError();
  static void clearErrors();

private:
  std::string model_;
};

}  // namespace sc::mesh
