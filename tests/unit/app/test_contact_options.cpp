// The contact-solver settings a problem file gives (app/run.hpp, contact_options()): IPOPT's default tol is
// 1e-12 for a hyperelastic body in Coulomb contact and 1e-10 otherwise; the problem's own [ipopt] tol wins.

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "symcontact/app/run.hpp"
#include "symcontact/model/problem_reader.hpp"

namespace symcontact {
namespace {

/// A body of material `law` against a plane, with the contact's `friction` lines and the `[ipopt]` lines.
ProblemSpec spec_of(const std::string& law, const std::string& friction, const std::string& ipopt = "") {
  const std::string text = "[problem]\ndimension = 2\n[[body]]\nname = \"block\"\nmesh = \"two_blocks.geo\"\n"
                           "group = \"lower\"\n[body.material]\n" + law +
                           "E = 1.0\nnu = 0.3\n[[contact]]\na = \"block.bottom\"\n" + friction +
                           "[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 0.0]\nnormal = [0.0, 1.0]\n" + ipopt;
  return parse_problem(text, "case.toml", std::string(SYMCONTACT_TEST_DATA) + "/geo");
}

/// The IPOPT tol the solves start from: the [ipopt] table's (or the default's) over IpoptOptions::tolerance.
double start_tolerance(const ProblemSpec& spec) {
  std::ostringstream quiet;
  const Logger log(quiet, Verbosity::kQuiet);
  const IpoptOptions& o = contact_options(spec, log).friction.contact.ipopt;
  const auto it = o.numeric_options.find("tol");
  return it != o.numeric_options.end() ? it->second : o.tolerance;
}

TEST(ContactOptions, HyperelasticBodyInCoulombContactTakesTheTighterIpoptTolerance) {
  const std::string coulomb = "friction = \"coulomb\"\nmu = 0.3\n";
  const std::string neo = "model = \"neo_hookean\"\n";
  EXPECT_EQ(start_tolerance(spec_of(neo, coulomb)), kFiniteStrainCoulombIpoptTolerance);
  EXPECT_EQ(start_tolerance(spec_of("", coulomb)), IpoptOptions{}.tolerance);
  EXPECT_EQ(start_tolerance(spec_of(neo, "")), IpoptOptions{}.tolerance);
  EXPECT_EQ(start_tolerance(spec_of(neo, "friction = \"tresca\"\ntau = 0.01\n")), IpoptOptions{}.tolerance);
  EXPECT_EQ(start_tolerance(spec_of(neo, coulomb, "[ipopt]\ntol = 1e-9\n")), 1e-9);
  // acceptable_tol follows IpoptOptions::tolerance, which stays at its default.
  std::ostringstream quiet;
  EXPECT_EQ(contact_options(spec_of(neo, coulomb), Logger(quiet, Verbosity::kQuiet)).friction.contact.ipopt.tolerance,
            IpoptOptions{}.tolerance);
  EXPECT_LT(kFiniteStrainCoulombIpoptTolerance, IpoptOptions{}.tolerance);
}

}  // namespace
}  // namespace symcontact
