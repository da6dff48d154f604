#pragma once
// Contact settings for tests that build the scene by hand: the declared defaults of the "Contact"
// list for what such a test does not set (a Plane obstacle in the obstacle frame, the Newton
// defaults), read from the declarations rather than repeated here; frictionless unless the test
// sets a friction law.
#include <sc/contact/ContactSettings.hpp>
#include <sc/core/Parameters.hpp>

namespace sc::contact::testing {

inline ContactSettings defaultContactSettings()
{
  Teuchos::ParameterList deck;
  core::validateParameters(deck, *ContactSettings::getValidParameters(), "test");
  ContactSettings s = ContactSettings::fromParameters(deck, 2);  // tests set point and normal
  s.frictionLaw = FrictionLaw::None;
  return s;
}

}  // namespace sc::contact::testing
