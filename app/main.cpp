// tsf: tangible scalar fields. One binary, one subcommand per job.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "app/commands.h"
#include "app/large_blocks.h"
#include "gen/util/error.h"
#include "gen/util/temp_files.h"

namespace tsf::cli {
namespace {
std::string g_invocation;
}
const std::string& invocation() { return g_invocation; }
void setInvocation(int argc, char** argv) {
    g_invocation = "tsf";
    for (int i = 1; i < argc; ++i) {
        // File names only: a shared .scad must not carry the folders of the
        // person who made it. A path is an argument (or the value of an
        // --option=value) whose folder exists; "km/h" stays as it is.
        std::string arg = argv[i];
        const size_t eq = arg.rfind("--", 0) == 0 ? arg.find('=') : std::string::npos;
        const std::string value = eq == std::string::npos ? arg : arg.substr(eq + 1);
        const std::filesystem::path path(value);
        std::error_code ec;
        if (path.has_parent_path() && path.has_filename() && std::filesystem::is_directory(path.parent_path(), ec))
            arg = (eq == std::string::npos ? std::string() : arg.substr(0, eq + 1)) + path.filename().string();
        const bool plain = arg.find_first_of(" \t'\"\\$") == std::string::npos && !arg.empty();
        g_invocation += " " + (plain ? arg : "'" + arg + "'");
    }
}
}  // namespace tsf::cli

int main(int argc, char** argv) {
    tsf::cli::setUpLargeBlocks();  // a model's large arrays on huge pages, reused once freed
    tsf::cli::setInvocation(argc, argv);
    tsf::installTempFileCleanup();  // no temporary file outlives a signal or a file-size limit
    CLI::App app{"tsf " TSF_VERSION " - turn a 2D scalar field into something you can feel:\n"
                 "a 3D-printable model of hexagonal pillars (STL, 3MF, OpenSCAD) or a surface\n"
                 "rendered on a force-feedback device."};
    app.require_subcommand(1);
    app.set_version_flag("--version", "tsf " TSF_VERSION);
    app.footer("Run 'tsf <command> --help' for the options of one command.\n"
               "Exit codes: 0 ok; 1 a check failed (or an internal error: a bug to report);\n"
               "2 bad input, a bad option, or an output\n"
               "that cannot be written (missing folder, no permission, disk full, an output\n"
               "that would overwrite an input or another output); 3 only when an external\n"
               "tool (openscad, node, prusa-slicer) failed or is missing; 4 a device failed;\n"
               "130 interrupted (Ctrl-C); ended by another signal, 128 + its number (143 SIGTERM).");
    tsf::cli::addGenCommand(app);
    tsf::cli::addInfoCommand(app);
    tsf::cli::addRenderCommand(app);
    tsf::cli::addVerifyCommand(app);
    tsf::cli::addFeelCommand(app);
    tsf::cli::addPrintCheckCommand(app);
    tsf::cli::addCouponCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::RuntimeError& e) {
        return e.get_exit_code();  // a command's own exit code (kExit*)
    } catch (const CLI::ParseError& e) {
        // Help and version are successes; every other parse error is bad input.
        const int code = app.exit(e);
        return code == 0 ? 0 : tsf::cli::kExitBadInput;
    } catch (const tsf::InputError& e) {
        std::fprintf(stderr, "tsf: error: %s\n", e.what());
        return tsf::cli::kExitBadInput;
    } catch (const std::logic_error& e) {
        // A broken precondition inside tsf or a library it uses (CGAL's
        // checks throw rather than abort): a bug, never the user's input.
        std::fprintf(stderr,
                     "tsf: internal error: %s\ntsf: this is a bug in tsf; nothing was written. Please report it with the "
                     "command and its input file.\n",
                     e.what());
        return tsf::cli::kExitCheckFailed;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tsf: error: %s\n", e.what());
        return tsf::cli::kExitToolFailed;
    }
    return 0;
}
