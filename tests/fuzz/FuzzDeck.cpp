// libFuzzer target: an XML input deck read and validated exactly as `stresscontact DECK` does
// (sc::app::readAndValidateDeck: Teuchos' XML parser, the strict number checks, duplicate keys,
// validation against the master list, defaults). An sc::core::InputError is the expected answer
// to a bad deck; any other exception, a crash, a sanitizer report or a hang is a finding.
#include <cstddef>
#include <cstdint>

#include <sc/core/Error.hpp>

#include "DeckParameters.hpp"
#include "FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string path = sc::fuzz::writeInput(data, size, ".xml");
  try {
    sc::app::readAndValidateDeck(path, {}, "");
  } catch (const sc::core::InputError&) {
  }
  return 0;
}
