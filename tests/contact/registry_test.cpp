#include "contact/registry.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace pound {
namespace {

TEST(ContactRegistry, HasEveryModelNamedInTheIssue) {
  for (const char* name : {"stereomechanical", "lve", "mlve", "nlve", "hertzdamp", "hertzdamp-ye",
                           "kelvin-ye", "hc-linear", "hc-hertz"}) {
    EXPECT_EQ(find_contact_model(name, "test").name, name);
  }
  EXPECT_EQ(contact_models().size(), 9u);
}

TEST(ContactRegistry, UnknownNameListsValidOnes) {
  try {
    find_contact_model("hertz-damp", "study.ini:3: key 'contact.model'");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("study.ini:3"), std::string::npos);
    EXPECT_NE(msg.find("hertzdamp-ye"), std::string::npos);
    EXPECT_NE(msg.find("hc-hertz"), std::string::npos);
  }
}

TEST(ContactRegistry, TheDampedSearsModelIsKnownByItsNameOnly) {
  EXPECT_TRUE(is_sears_model("sears"));
  for (const char* other : {"Sears", "sears ", "hc-linear", ""})
    EXPECT_FALSE(is_sears_model(other));
  EXPECT_EQ(every_contact_model_name(), contact_model_names() + ", sears");
  EXPECT_THROW(find_contact_model(kSearsModelName, "t"), InputError);  // no lumped law
}

TEST(ContactLaws, LinearViscoelasticIsTensileNearSeparationAsPublished) {
  ContactParameters p;
  p.k = 1e6;
  p.e = 0.5;
  p.m1 = p.m2 = 1.0;
  auto law = find_contact_model("lve", "t").make(p);
  EXPECT_LT(law->force(1e-6, -1.0, 1.0), 0.0);
  auto hc = find_contact_model("hc-linear", "t").make(p);
  EXPECT_EQ(hc->force(1e-6, -10.0, 1.0), 0.0);  // clamped: no adhesion
  // Hunt-Crossley at zero rate is the elastic law.
  EXPECT_DOUBLE_EQ(hc->force(1e-3, 0.0, 1.0), 1e3);
}

}  // namespace
}  // namespace pound
