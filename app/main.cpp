// fpmshell command line (model-format.md): run, check, partition, --version. Exit codes: 0 success,
// 1 the run failed, 2 the model or a file it names is invalid.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "fpmshell/core/communicator.hpp"
#include "fpmshell/core/errors.hpp"
#include "fpmshell/driver/partition_report.hpp"
#include "fpmshell/driver/run_driver.hpp"
#include "fpmshell/io/atomic_file.hpp"
#include "fpmshell/io/lsdyna_deck.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/solver/unit_partition.hpp"

namespace {

constexpr int k_exit_invalid = 2;

const char* k_footer = R"(Examples:
  fpmshell check examples/spherical_cap_elastic/model.yaml
  fpmshell run examples/spherical_cap_elastic/model.yaml -o results/cap --set control.end_time=5e-4
  fpmshell run examples/square_tube/model.yaml -o results/tube --restart-every 600
  fpmshell run examples/square_tube/model.yaml -o results/tube --restart-every 600 --resume
  fpmshell partition examples/square_tube/model.yaml --parts 4
  fpmshell check examples/decks/plate_drop/plate_drop.k
  fpmshell convert examples/decks/plate_drop/plate_drop.k -o plate_drop.yaml
Results: history.csv, energy.csv, fields.pvd (open in ParaView), summary.json, log.txt.)";

/// `fpmshell convert`: the deck's YAML model, its mesh file named relative to the YAML file.
int convert_deck(const std::string& deck, std::string yaml, bool overwrite) {
    namespace fs = std::filesystem;
    if (!fpmshell::is_keyword_deck(deck))
        throw fpmshell::InputError(fpmshell::input_error_text(
            deck, 0, "", "convert reads LS-DYNA keyword decks (.k, .key, .dyn, .kw)"));
    if (yaml.empty())
        yaml = (fs::path(deck).parent_path() / fs::path(deck).stem()).string() + ".yaml";
    std::error_code ec;
    if (fs::exists(yaml, ec) && !overwrite)
        throw fpmshell::InputError(fpmshell::input_error_text(
            yaml, 0, "", "the file exists; give --overwrite to replace it"));
    const fs::path from = fs::absolute(fs::path(yaml)).parent_path();
    fs::path mesh = fs::relative(fs::absolute(deck), from, ec);
    if (ec || mesh.empty()) mesh = fs::absolute(deck);
    const fpmshell::DeckTranslation t = fpmshell::translate_lsdyna_deck(deck, mesh.string());
    std::string text = "# translated by fpmshell " FPMSHELL_VERSION " from " + deck + "\n";
    for (const std::string& n : t.notes) text += "# note: " + n + "\n";
    text += t.yaml;
    try {
        fpmshell::write_file_atomic(yaml, text);
    } catch (const std::exception& e) {
        std::cerr << "error: " << yaml << ": " << e.what() << "\n";
        return 1;
    }
    for (const std::string& n : t.notes) std::cout << "note: " << n << "\n";
    std::cout << "wrote " << yaml << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    // Under mpirun, every rank runs this program; the messages come from rank 0 (every rank
    // reads the same model and meets the same errors).
    const fpmshell::MpiSession mpi(argc, argv);
    const fpmshell::Communicator& comm = fpmshell::Communicator::world();
    CLI::App app{
        "fpmshell — explicit finite particle method for the nonlinear dynamics of thin shells"};
    app.footer(k_footer);
    app.set_version_flag("--version", std::string("fpmshell ") + FPMSHELL_VERSION);
    app.require_subcommand(1);

    std::string model_path, out_dir;
    std::vector<std::string> overrides;
    int threads = 0;
    bool quiet = false, overwrite = false, resume = false;
    double restart_every = 0;

    CLI::App* run = app.add_subcommand("run", "run a model and write its results");
    run->add_option("model", model_path, "model file (YAML) or LS-DYNA deck (.k, .key, .dyn)")
        ->required();
    run->add_option("-o,--output", out_dir, "result folder (default results/<model file stem>)");
    run->add_option("--threads", threads, "number of threads (default: all)")
        ->check(CLI::Range(1, 4096));
    run->add_flag("--quiet", quiet, "a progress line every ~5 % instead of a live line");
    run->add_flag("--overwrite", overwrite, "replace results of another model in the folder");
    run->add_option("--set", overrides,
                    "override a scalar of the model, e.g. control.end_time=2e-3");
    run->add_option("--restart-every", restart_every,
                    "write the restart file DIR/restart.bin every this many wall-clock seconds and "
                    "at the end")
        ->check(CLI::PositiveNumber);
    run->add_flag("--resume", resume,
                  "continue the run in the result folder from its restart file (a later end_time "
                  "may be --set)");

    CLI::App* check = app.add_subcommand("check", "parse and validate a model, print a summary");
    check->add_option("model", model_path, "model file (YAML) or LS-DYNA deck (.k, .key, .dyn)")
        ->required();
    check->add_option("--set", overrides, "override a scalar of the model");

    int parts = 1;
    CLI::App* partition = app.add_subcommand(
        "partition",
        "cut a model into parts for a distributed run, print each part's load and halo");
    partition->add_option("model", model_path, "model file (YAML) or LS-DYNA deck")->required();
    partition->add_option("--parts", parts, "number of parts")
        ->required()
        ->check(CLI::Range(1, 1 << 20));
    partition->add_option("--set", overrides, "override a scalar of the model");

    std::string yaml_path;
    CLI::App* convert = app.add_subcommand(
        "convert", "translate an LS-DYNA deck into a YAML model file and print what was ignored");
    convert->add_option("deck", model_path, "LS-DYNA keyword deck (.k, .key, .dyn)")->required();
    convert->add_option("-o,--output", yaml_path,
                        "the YAML model file to write (default: <deck stem>.yaml beside it)");
    convert->add_flag("--overwrite", overwrite, "replace an existing file");

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return k_exit_invalid;
    }

    try {
        if (convert->parsed()) return convert_deck(model_path, yaml_path, overwrite);
        const fpmshell::Model model = fpmshell::is_keyword_deck(model_path)
                                          ? fpmshell::read_lsdyna_deck(model_path, overrides)
                                          : fpmshell::read_model(model_path, overrides);
        if (check->parsed()) {
            std::cout << fpmshell::model_summary(model);
            return 0;
        }
        if (partition->parsed()) {
            if (parts > 1 && !fpmshell::partitioning_available()) {
                std::cerr << "error: this build has no METIS (install libmetis-dev and build "
                             "again): it cannot cut a model into "
                          << parts << " parts\n";
                return k_exit_invalid;
            }
            std::cout << fpmshell::partition_report(model, parts);
            return 0;
        }
        fpmshell::RunOptions opt;
        opt.output_dir = out_dir.empty() ? std::filesystem::path("results") /
                                               std::filesystem::path(model_path).stem()
                                         : std::filesystem::path(out_dir);
        opt.threads = threads;
        opt.quiet = quiet;
        opt.overwrite = overwrite;
        opt.restart_every = restart_every;
        opt.resume = resume;
        return fpmshell::run_model(model, opt);
    } catch (const fpmshell::InputError& e) {
        if (comm.root()) std::cerr << "error: " << e.what() << "\n";
        return k_exit_invalid;
    } catch (const std::exception& e) {
        // an error of one rank alone (a file rank 0 could not write) would leave the others
        // waiting: it stops them all
        std::cerr << "error";
        if (comm.distributed()) std::cerr << " on rank " << comm.rank();
        std::cerr << ": " << e.what() << "\n";
        if (comm.distributed()) comm.abort(1);
        return 1;
    }
}
