// grass-measure: the measurement tools, one subcommand each.
//   bench      frame cost and image error of the quality presets (docs/quality.md)
//   tier-cost  the frame cost of each tier, design map and optional feature (docs/three-tiers.md,
//              docs/records/feature-cost.md)
//   popping    popping in the transition zones against blades everywhere (docs/records/popping.md)
//   dynamics   the cost of responsive grass: wind, colliders, the interaction pass (docs/records/responsive.md)
//   first-frame  the first windy frame with and without grass_prepare_pipelines (docs/records/prepare-pipelines.md)
//   tier-sweep each tier alone against the blades from every elevation and sun (docs/records/tier-sweep.md)
#include "cli.hpp"
#include "measure.hpp"
#include "tool.hpp"

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    CLI::App app("grass-measure: measurements of grass's cost and image quality on the headless hosts.",
                 "grass-measure");
    app.require_subcommand(0, 1); // none: the message below; an unknown one: CLI11 names it
    const grass_measure::Subcommand subcommands[] = {
        grass_measure::add_bench(app),    grass_measure::add_tier_cost(app),   grass_measure::add_popping(app),
        grass_measure::add_dynamics(app), grass_measure::add_first_frame(app), grass_measure::add_tier_sweep(app)};
    const int parsed = grass_sample::parse(app, argc, argv);
    if (parsed >= 0) return parsed;
    for (const grass_measure::Subcommand& s : subcommands) {
        if (!s.app->parsed()) continue;
        try {
            return s.run();
        } catch (const grass_sample::Failure& e) {
            return grass_sample::fail(("grass-measure " + s.app->get_name()).c_str(), e.what());
        }
    }
    std::fprintf(
        stderr,
        "grass-measure: a subcommand is required (bench, tier-cost, popping, dynamics, first-frame or tier-sweep)\n"
        "Run with --help for more information.\n");
    return 2;
}
