// output.contacts: contact_events.csv of a two-disk impact and a disk-on-wall impact against the
// closed forms of both normal laws, the per-snapshot contacts CSV, and a resume that writes the
// same events as an uninterrupted run.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "cli/run/run_loop.hpp"
#include "io/checkpoint.hpp"
#include "io/contact_csv.hpp"
#include "physics/reference_values.hpp"
#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "support/impacts_scenario.hpp"
#include "support/run_dir.hpp"
#include "talus/closed_forms.hpp"
#include "talus/pair_parameters.hpp"

namespace fs = std::filesystem;

namespace talus {
namespace {

using testing::fresh_dir;

Scenario impacts(const std::string& law, double restitution, double speed) {
  return testing::two_impacts(law, restitution, speed, "verlet",
                              "contacts = true\nthermo_interval = 0.001\n"
                              "snapshot_interval = 0.001\ncheckpoint_interval = 0.001");
}

std::vector<ContactEvent> run_events(const Scenario& s, const fs::path& dir, double stop_at = -1) {
  cli::RunOptions o;
  o.quiet = true;
  o.stop_at = stop_at;
  cli::start_run(s, build_scenario(s), dir.string(), o);
  return read_contact_events((dir / "contact_events.csv").string());
}

// What the closed forms need of a contact: its reduced mass, and the mixed pair's parameters.
struct Impact {
  double m_eff;
  PairParameters p;
};

Impact pair_impact(const Scenario& s) {
  const BuiltScenario b = build_scenario(s);
  const double m = b.world.particles.mass[0];
  return {0.5 * m, mix(b.world.materials[0], b.world.materials[0], s.simulation.impact_speed)};
}

Impact wall_impact(const Scenario& s) {
  const BuiltScenario b = build_scenario(s);
  return {b.world.particles.mass[2],
          mix(b.world.materials[0], b.world.materials[1], s.simulation.impact_speed)};
}

// Each event's numbers are within `tolerance` of what the law says: the start and end are put
// between steps from the overlap's rate, and the peaks are the largest of the steps'. Both are
// good to (pi dt / t_c)^2 ~ 4e-5 at dt = t_c / 500, and the integrator's own error at that step
// is of the same order; 5e-4 leaves room for that and still fails a duration rounded to whole
// steps (an error up to dt / t_c = 2e-3).
constexpr double duration_tolerance = 5e-4;

TEST(ContactEvents, HertzImpactsLastAndPeakAsTheClosedFormsSay) {
  const double v = 0.1; // each disk's speed: the pair meets at 2 v, the falling disk hits at 2 v
  const Scenario s = impacts("hertz", 1.0, v);
  const auto events = run_events(s, fresh_dir("contact_events_hertz"));
  ASSERT_EQ(events.size(), 2U);
  for (const ContactEvent& e : events) {
    const bool wall = e.wall >= 0;
    SCOPED_TRACE(wall ? "disk on the rigid floor" : "two disks");
    EXPECT_EQ(e.particle, wall ? 2U : 0U);
    EXPECT_EQ(e.partner, wall ? -1 : 1);
    EXPECT_FALSE(e.touching);
    const Impact i = wall ? wall_impact(s) : pair_impact(s);
    const double r_eff = wall ? 0.005 : 0.0025;
    const double rho = hertz_rho(i.p.effective_young, r_eff);
    const double speed = 2.0 * v;
    const double t_c = hertz_collision_time(i.m_eff, rho, speed);
    const double xi_max = hertz_max_overlap(i.m_eff, rho, speed);
    EXPECT_NEAR(e.duration() / t_c, 1.0, duration_tolerance);
    EXPECT_NEAR(e.peak_overlap / xi_max, 1.0, duration_tolerance);
    EXPECT_NEAR(e.peak_normal_force / (rho * std::pow(xi_max, 1.5)), 1.0, duration_tolerance);
    EXPECT_NEAR(e.impact_speed / speed, 1.0, duration_tolerance);
    EXPECT_NEAR(e.rebound_speed / speed, 1.0, duration_tolerance);
    // each touches when its gap of 1 mm has closed at 2 v
    EXPECT_NEAR(e.start / (0.001 / speed), 1.0, duration_tolerance);
  }
}

TEST(ContactEvents, DampedLinearImpactsLastAndReboundAsTheClosedFormsSay) {
  const double v = 0.1, e_asked = 0.5;
  const Scenario s = impacts("linear", e_asked, v);
  const auto events = run_events(s, fresh_dir("contact_events_linear"));
  ASSERT_EQ(events.size(), 2U);
  for (const ContactEvent& e : events) {
    const bool wall = e.wall >= 0;
    SCOPED_TRACE(wall ? "disk on the rigid floor" : "two disks");
    const Impact i = wall ? wall_impact(s) : pair_impact(s);
    const double k = i.p.normal_stiffness;
    const double eta = 2.0 * linear_damping_ratio(e_asked) * std::sqrt(k * i.m_eff);
    EXPECT_NEAR(e.duration() / linear_collision_time(k, eta, i.m_eff), 1.0, duration_tolerance);
    // The dashpot's force starts at the touch, between two steps, at eta u: the integrator's
    // velocity after that step is off by up to half a step of it, (eta u / m_eff) (dt / 2),
    // or zeta omega dt = zeta pi / 500 = 1.6e-3 of u at e = 0.5 (zeta = 0.255, the
    // never-attractive dashpot's; docs/accuracy.md).
    const double onset = 2e-3;
    EXPECT_NEAR(e.impact_speed / (2.0 * v), 1.0, onset);
    EXPECT_NEAR(e.rebound_speed / e.impact_speed, e_asked, onset);
  }
}

// At t_c / 50 the restitution an event records is the one the grains really got, within 1e-3:
// its impact speed is their approach speed before the touch (2 v), its rebound speed the speed
// they part at (in free flight after the contact), for both laws, restitutions from 0.3 to 1,
// head-on and against a rigid floor, with either integrator. The parting falls between looks;
// the speed the force still gives after the last look is integrated over the overlap's fall, the
// force's elastic part as xi^p and its dashpot part as xi^(p - 1) (p = 1 linear, 3/2 Hertz), up
// to where the never-attractive force ends (measured: at most 4.3e-4 of the impact speed, Verlet,
// linear, e = 1). The impact speed is the approach at the look before the touch: the first look
// in contact carries the integrator's start-up (Gear's corrector gives the first step's force
// 251/360 of a step, not the part since the touch), which put up to 9.5e-3 into it.
TEST(ContactEvents, RecordedRestitutionIsTheGrainsOwnAtFiftyStepsAContact) {
  const double v = 0.1;
  for (const std::string integrator : {"gear", "verlet"}) {
    for (const std::string law : {"hertz", "linear"}) {
      for (const double restitution : {0.3, 0.5, 0.9, 1.0}) {
        SCOPED_TRACE(integrator + ", " + law + ", e = " + std::to_string(restitution));
        Scenario s = testing::two_impacts(law, restitution, v, integrator, "");
        s.simulation.timestep_factor = 50.0;
        BuiltScenario b = build_scenario(s);
        Simulation sim(std::move(b.world), b.config);
        ContactEventLog log;
        log.remember(sim);
        std::vector<ContactEvent> ended;
        while (sim.time() < 0.02) {
          sim.step();
          for (const ContactEvent& e : log.observe(sim)) ended.push_back(e);
        }
        ASSERT_EQ(ended.size(), 2U);
        const auto& p = sim.world().particles;
        for (const ContactEvent& e : ended) {
          const bool wall = e.wall >= 0;
          SCOPED_TRACE(wall ? "on the floor" : "two disks");
          const double got =
              wall ? p.velocity[2].y / (2.0 * v) : (p.velocity[1].x - p.velocity[0].x) / (2.0 * v);
          EXPECT_NEAR(e.impact_speed / (2.0 * v), 1.0, 1e-3);
          EXPECT_NEAR(e.rebound_speed / (2.0 * v), got, 1e-3);
          EXPECT_NEAR(e.rebound_speed / e.impact_speed, got, 1e-3);
        }
      }
    }
  }
}

// A run stopped while both contacts are open and resumed writes the events an uninterrupted run
// writes, to the bit; the snapshots' CSV lists the contacts that touch then.
TEST(ContactEvents, ResumeWritesTheSameEventsAndSnapshotsListTheContacts) {
  const Scenario s = impacts("hertz", 0.7, 0.1);
  const fs::path whole = fresh_dir("contact_events_whole"),
                 parts = fresh_dir("contact_events_parts");
  run_events(s, whole);
  // both touch from 5 ms on (1 mm at 0.2 m/s) for about 5 ms
  cli::RunOptions o;
  o.quiet = true;
  o.stop_at = 0.0075;
  ASSERT_EQ(cli::start_run(s, build_scenario(s), parts.string(), o), cli::exit_stopped);
  o.stop_at = -1.0;
  ASSERT_EQ(cli::resume_run(parts.string(), o), cli::exit_completed);
  EXPECT_EQ(read_file((parts / "contact_events.csv").string()),
            read_file((whole / "contact_events.csv").string()));
  // snapshot 7 at 7 ms: both contacts touching, with the grains' ids
  const std::string snapshot = read_file((whole / "snapshots" / "contacts_000007.csv").string());
  EXPECT_EQ(snapshot.substr(0, snapshot.find('\n')),
            "time,particle,partner,wall,overlap,normal_force,tangential_force,x,y");
  EXPECT_NE(snapshot.find(",0,1,-1,"), std::string::npos) << snapshot;
  EXPECT_NE(snapshot.find(",2,-1,0,"), std::string::npos) << snapshot;
  fs::remove_all(whole);
  fs::remove_all(parts);
}

} // namespace
} // namespace talus
