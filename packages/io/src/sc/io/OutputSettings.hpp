#pragma once
// The "Output" sublist of the input deck: where and what to write (docs/output.md).

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <array>
#include <string>

namespace sc::io {

class OutputSettings {
public:
  /// Name of the sublist in the deck.
  static constexpr const char* sublistName = "Output";

  /// Every key with its default and documentation (cached; Belos/Tempus convention).
  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();

  /// Defaults only.
  OutputSettings();

  /// Validate \p outputSublist (a copy is completed with defaults) and read it, for a list that
  /// was not validated with the deck (tests, tools). Throws sc::core::InputError naming the key
  /// (as Output/<key>) for unknown keys, wrong types and bad values.
  explicit OutputSettings(const Teuchos::ParameterList& outputSublist);

  /// Read a validated "Output" sublist (the deck's, validated once with the whole deck); throws
  /// InputError for an empty Directory and a Base name that is empty or holds a '/'.
  static OutputSettings fromParameters(const Teuchos::ParameterList& validatedOutput);

  std::string directory;                ///< Output/Directory
  std::string baseName;                 ///< Output/Base name
  bool writeXdmf;                       ///< Output/Write XDMF
  bool writeContactCsv;                 ///< Output/Write contact CSV
  std::array<double, 3> momentPoint{};  ///< Output/Moment point (x0 of the reactions' moments)

private:
  struct Unread {};
  explicit OutputSettings(Unread) {}
};

}  // namespace sc::io
