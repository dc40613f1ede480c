// Subcommands of the tsf binary. Each is defined in this folder (app/, the
// application: the only code that includes CLI11) and registered by main.cpp;
// a command reports failure by throwing CLI::RuntimeError(exit_code) (see
// kExit* below) or tsf::InputError. The work itself is done by the libraries'
// entry points (docs/design.md), which know nothing of the command line.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace tsf::cli {

/// Exit codes shared by all subcommands.
inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;   ///< a requested check (verify) did not pass
inline constexpr int kExitBadInput = 2;      ///< bad input file or parameter, or an output that cannot be written
inline constexpr int kExitToolFailed = 3;    ///< an external tool (openscad, ...) failed or is missing
inline constexpr int kExitDeviceFailed = 4;  ///< a haptic device could not be used
inline constexpr int kExitInterrupted = 130; ///< SIGINT

/// The command line tsf was started with ("tsf gen field.csv -o m.stl"), for
/// file headers: every path shortened to its file name, so no folder of the
/// user's travels with a shared file.
const std::string& invocation();
void setInvocation(int argc, char** argv);

void addGenCommand(CLI::App& app);     // gen_command.cpp
void addInfoCommand(CLI::App& app);    // gen_command.cpp
void addRenderCommand(CLI::App& app);  // render_command.cpp
void addVerifyCommand(CLI::App& app);  // verify_command.cpp
void addFeelCommand(CLI::App& app);    // feel_command.cpp
void addPrintCheckCommand(CLI::App& app);  // print_check_command.cpp
void addCouponCommand(CLI::App& app);  // coupon_command.cpp

}  // namespace tsf::cli
