// `course`: the trusted grading and course tool (SPEC.md, `course`). It
// never links lab code: it runs the `lab` executable in child processes and
// decides pass or fail from the data files and its own reference code.
#include <CLI/CLI.hpp>

#include <cstdio>

#include "framework/error.hpp"
#include "grading/commands.hpp"
#include "grading/gradescope.hpp"

int main(int argc, char** argv) {
    CLI::App app{"course: grade the labs, bless references, release the student version"};
    app.require_subcommand(1);

    grading::GradeOptions g;
    auto* grade = app.add_subcommand("grade", "Grade labs offscreen and write the reports");
    grade->add_option("LAB", g.labs, "Labs to grade (default: all)");
    grade->add_option("--lab", g.lab_binary, "The lab executable to grade (default: beside course)");
    grade->add_option("--out", g.out, "Report directory (default build/grade)");
    const char* backend_help =
        "auto|osmesa|egl (default $LAB_BACKEND, else auto: EGL, then OSMesa)";
    grade->add_option("--backend", g.backend, backend_help);
    grade->add_option("--jobs", g.jobs, "Labs graded in parallel")->check(CLI::Range(1, 64));
    grade->add_option("--timeout", g.timeout_seconds, "Seconds per lab (default 60)")
        ->check(CLI::Range(1.0, 3600.0));
    grade->add_option("--run-as", g.run_as, "Run the child as this user (when root)");

    grading::BlessOptions b;
    auto* bless = app.add_subcommand("bless", "Re-render the reference images from this build");
    bless->add_option("LAB", b.labs, "Labs to bless (default: all)");
    bless->add_option("--lab", b.lab_binary, "The lab executable (default: beside course)");
    bless->add_option("--backend", b.backend, backend_help);

    std::string release_out;
    auto* release = app.add_subcommand("release", "Write the student version of the repository");
    release->add_option("--out", release_out, "Directory to write (must not exist or be empty)")
        ->required();

    std::string gradescope_out;
    auto* gradescope = app.add_subcommand("gradescope", "Write a Gradescope autograder folder");
    gradescope->add_option("--out", gradescope_out, "Directory to write")->required();

    // Hidden: the autograder's run_autograder (grading/gradescope/) calls it
    // when a submission cannot be graded.
    std::string ng_reason, ng_log, ng_out;
    auto* not_graded =
        app.add_subcommand("not-graded", "Write reports that fail every check with a reason");
    not_graded->group("");
    not_graded->add_option("--reason", ng_reason, "Why nothing was graded")->required();
    not_graded->add_option("--log", ng_log, "A log whose last 200 lines go into the output");
    not_graded->add_option("--out", ng_out, "Report directory")->required();

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "course: %s\nRun 'course --help' for usage.\n", e.what());
        return 2;
    }

    try {
        if (*grade) return grading::grade_command(g);
        if (*bless) return grading::bless_command(b);
        if (*release) return grading::release_command(release_out);
        if (*gradescope) return grading::gradescope_command(gradescope_out);
        if (*not_graded) return grading::not_graded_command(ng_reason, ng_log, ng_out);
    } catch (const fw::Error& e) {
        std::fprintf(stderr, "course: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "course: internal error: %s\n", e.what());
        return 2;
    }
    return 0;
}
