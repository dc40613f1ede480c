// Subcommands of the tsf binary. Each is defined next to the library it drives
// and registered by main.cpp; a command reports failure by throwing
// CLI::RuntimeError(exit_code) (see kExit* below) or tsf::InputError.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace tsf::cli {

/// Exit codes shared by all subcommands.
inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;   ///< a requested check (verify) did not pass
inline constexpr int kExitBadInput = 2;      ///< bad input file or parameter
inline constexpr int kExitToolFailed = 3;    ///< an external tool (openscad, ...) failed or is missing
inline constexpr int kExitDeviceFailed = 4;  ///< a haptic device could not be used
inline constexpr int kExitInterrupted = 130; ///< SIGINT

/// The command line tsf was started with ("tsf gen field.csv -o m.stl"), for file headers.
const std::string& invocation();
void setInvocation(int argc, char** argv);

void addGenCommand(CLI::App& app);     // gen/cli/gen_command.cpp
void addInfoCommand(CLI::App& app);    // gen/cli/info_command.cpp
void addRenderCommand(CLI::App& app);  // gen/cli/render_command.cpp
void addVerifyCommand(CLI::App& app);  // verify/cli/verify_command.cpp
void addFeelCommand(CLI::App& app);    // haptics/cli/feel_command.cpp

}  // namespace tsf::cli
