// libFuzzer target: `--set` overrides. Each line of the input is one `--set` argument applied to
// the shipped input/hertz2d.xml through sc::app::readAndValidateDeck, as
// `stresscontact input/hertz2d.xml --set LINE1 --set LINE2 ...` does (sc::core::applyOverride:
// key path, sublists and templates, strict parsing by the key's type; then validation).
// sc::core::InputError is expected; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <sc/core/Error.hpp>

#include "DeckParameters.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::vector<std::string> overrides;
  std::string line;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') {
      overrides.push_back(line);
      line.clear();
    } else {
      line.push_back(static_cast<char>(data[i]));
    }
  }
  if (!line.empty()) overrides.push_back(line);
  if (overrides.size() > 16)
    return -1;  // reject: a command line has a few overrides, not thousands
  try {
    sc::app::readAndValidateDeck(SC_FUZZ_BASE_DECK, overrides, "");
  } catch (const sc::core::InputError&) {
  }
  return 0;
}
