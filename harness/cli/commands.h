// The vobench subcommands. Each registers its options on the app and returns a callback
// that runs it and yields the process exit code (0 ok, 1 check found violations,
// 2 bad usage or bad input).
#pragma once
#include <functional>

#include <CLI/CLI.hpp>

namespace vob {

using Command = std::function<int()>;
Command add_list_command(CLI::App& app);
Command add_generate_command(CLI::App& app);
Command add_order_command(CLI::App& app);
Command add_check_command(CLI::App& app);
Command add_run_command(CLI::App& app);
Command add_report_command(CLI::App& app);
Command add_reproduce_command(CLI::App& app);
Command add_validate_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_merge_command(CLI::App& app);

}  // namespace vob
