// vobench: visibility-ordering algorithms side by side, judged by one z-buffer oracle.
#include <cstdio>
#include <iostream>
#include <map>

#include "harness/cli/commands.h"
#include "harness/scene/input_error.h"

int main(int argc, char** argv) {
  CLI::App app{"vobench: visibility orderings for volume rendering, checked by one oracle"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help for every subcommand");
  std::map<CLI::App*, vob::Command> commands;
  const auto add = [&](vob::Command (*f)(CLI::App&)) {
    const size_t before = app.get_subcommands({}).size();
    vob::Command c = f(app);
    commands[app.get_subcommands({})[before]] = c;
  };
  add(vob::add_list_command);
  add(vob::add_generate_command);
  add(vob::add_order_command);
  add(vob::add_check_command);
  add(vob::add_run_command);
  add(vob::add_report_command);
  add(vob::add_reproduce_command);
  add(vob::add_validate_command);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    for (auto& [sub, run] : commands)
      if (sub->parsed()) return run();
  } catch (const vob::InputError& e) {
    std::fprintf(stderr, "vobench: %s\n", e.what());
    return 2;
  } catch (const std::logic_error& e) {
    std::fprintf(stderr, "vobench: internal error: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vobench: %s\n", e.what());
    return 2;
  }
  return 2;
}
