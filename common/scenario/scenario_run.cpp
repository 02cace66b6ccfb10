// Runs a scenario's shot on a fresh simulation, for the result JSON and for the plot.
#include <algorithm>

#include "scenario/scenario.h"

namespace pool::scenario {

Result<physics::ShotOutcome> runScenario(const Scenario& scenario) {
  using R = Result<physics::ShotOutcome>;
  physics::Simulation sim(scenario.spec, scenario.geometry);
  if (auto placed = sim.setBalls(scenario.balls); !placed)
    return R::fail("balls: " + placed.error());
  return sim.shoot(scenario.shot, scenario.options);
}

Result<physics::ShotOutcome> runForPlot(const Scenario& scenario,
                                        const physics::ShotOutcome& outcome) {
  if (scenario.options.sample_hz >= kPlotSampleHz) return Result<physics::ShotOutcome>::ok(outcome);
  Scenario sampled = scenario;
  sampled.options.sample_hz = kPlotSampleHz;
  return runScenario(sampled);
}

}  // namespace pool::scenario
