// grass-measure's subcommands. Each adds its command line to the tool's and returns the run
// that main calls when that subcommand is the one given.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace grass_measure {

struct Subcommand {
    CLI::App* app = nullptr;
    std::function<int()> run; // the exit status
};

Subcommand add_bench(CLI::App& measure);       // bench.cpp
Subcommand add_tier_cost(CLI::App& measure);   // tier_cost.cpp
Subcommand add_popping(CLI::App& measure);     // popping.cpp
Subcommand add_dynamics(CLI::App& measure);    // dynamics.cpp
Subcommand add_first_frame(CLI::App& measure); // first_frame.cpp
Subcommand add_tier_sweep(CLI::App& measure);  // tier_sweep.cpp

} // namespace grass_measure
