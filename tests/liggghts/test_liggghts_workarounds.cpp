// LIGGGHTS 3.8 defects hsrod works around (liggghts_workarounds.h).
#include "liggghts_session.h"

#include "error_special.h"
#include "universe.h"

#include <gtest/gtest.h>

#include <cstring>

namespace {

// ERROR lines must not be printed twice with garbage bytes.
// LIGGGHTS' Error::one/all print, in one of five errors of a "PUBLIC"
// build, SpecialMessages::generate_message(), a pointer into a destroyed
// std::string. Every hsrod instance must have that message switched off
// (it is generated only for version strings containing "PUBLIC") and keep
// the version number readable for restart files.
TEST(LiggghtsWorkarounds, ErrorMessagesCarryNoDanglingTip) {
  hsrod_test::LiggghtsSession session;
  const char *version = session.lammps()->universe->version;
  EXPECT_EQ(std::strstr(version, "PUBLIC"), nullptr) << version;
  EXPECT_NE(std::strstr(version, "LIGGGHTS-Public 3.8."), nullptr) << version;
  LAMMPS_NS::SpecialMessages messages(session.lammps());
  for (int k = 0; k < 20; k++) EXPECT_EQ(messages.generate_message(), nullptr);
}

}  // namespace
