// vobench: visibility-ordering algorithms side by side, judged by one z-buffer oracle.
#include <cstdio>
#include <iostream>
#include <map>
#include <vector>

#include "harness/bench/context.h"
#include "harness/cli/commands.h"
#include "harness/cli/error_line.h"
#include "harness/cli/huge_page_new.h"
#include "harness/cli/plugin_loader.h"
#include "harness/scene/input_error.h"

int main(int argc, char** argv) {
  {
    const vob::HugePagePolicy hp = vob::huge_page_policy();
    vob::set_allocation_context({{"huge_pages", hp.on},
                                 {"min_bytes", vob::kHugePageMinBytes},
                                 {"reuse_max_blocks", vob::kHugeReuseBlocks},
                                 {"reuse_max_bytes", vob::kHugeReuseBytes},
                                 {"kernel_thp", hp.kernel},
                                 {"why_off", hp.why}});
  }
  CLI::App app{"vobench: visibility orderings for volume rendering, checked by one oracle"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help for every subcommand");
  // Taken out of argv by load_plugin_options before CLI11 parses; declared for --help.
  std::vector<std::string> plugin_help;
  app.add_option("--plugin", plugin_help,
                 "load orderers from a shared library (before the subcommand; repeatable)")
      ->type_name("PATH.so");
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
  add(vob::add_compare_command);
  add(vob::add_merge_command);
  // Every failure is one line on stderr, "vobench: SUBCOMMAND: what: reason", exit 2 (3 for
  // an internal error): scripts and the fuzz suite read exactly that line.
  const auto fail = [&](const std::string& message, int code) {
    std::string where;
    for (auto& [sub, run] : commands)
      if (sub->parsed()) where = sub->get_name() + ": ";
    std::fprintf(stderr, "%s\n", vob::error_line("vobench: " + where + message).c_str());
    return code;
  };
  // Plugins first: their orderers are known to every subcommand (list, check, run, ...).
  std::vector<char*> args;
  try {
    args = vob::load_plugin_options(argc, argv);
  } catch (const std::exception& e) {
    return fail(e.what(), 2);
  }
  argc = static_cast<int>(args.size());
  argv = args.data();
  // CLI11 would only say that a subcommand is required; name the word it did not know.
  if (argc > 1 && argv[1][0] != '-') {
    std::string known;
    bool found = false;
    for (const CLI::App* sub : app.get_subcommands({})) {
      found = found || sub->get_name() == argv[1];
      known += (known.empty() ? "" : ", ") + sub->get_name();
    }
    if (!found) return fail("'" + std::string(argv[1]) + "' is not a subcommand (known: " + known + ")", 2);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --help-all
    return fail(e.what(), 2);
  }
  try {
    for (auto& [sub, run] : commands)
      if (sub->parsed()) return run();
  } catch (const vob::InputError& e) {
    return fail(e.what(), 2);
  } catch (const std::logic_error& e) {
    return fail(std::string("internal error: ") + e.what(), 3);
  } catch (const std::exception& e) {
    return fail(e.what(), 2);
  }
  return 2;
}
