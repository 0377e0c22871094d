#include "batch_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <map>

#include "batch.hpp"
#include "common.hpp"
#include "global_options.hpp"
#include "tactus/io/text_output.hpp"

namespace tactus::cli {
namespace {

namespace fs = std::filesystem;

// What libsndfile reads, by extension, for walking folders.
bool is_sound_file(const fs::path& path) {
    std::string e = path.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    for (const char* known : {".wav", ".flac", ".ogg", ".oga", ".opus", ".mp3", ".aif", ".aiff",
                              ".w64", ".rf64", ".caf", ".au"})
        if (e == known) return true;
    return false;
}

}  // namespace

void BatchOptions::add_to(CLI::App& command, const std::string& output_help,
                          const std::string& suffix) {
    this->command = command.get_name();
    command.add_option("inputs", inputs, "audio files or folders (- for stdin); several need -O")
        ->required()
        ->type_name("FILE|DIR|-");
    if (!output_help.empty()) command.add_option("-o,--output", output, output_help);
    command.add_option("-O,--output-dir", output_dir,
                       "folder for the outputs: DIR/<input's folder below the given one>/<name "
                       "without extension>" +
                           suffix + " (created if missing)");
    command.add_option("-j,--jobs", jobs, "files processed at once, one per thread")
        ->check(CLI::Range(1, 1024))
        ->capture_default_str();
    command.add_flag("--skip-existing", skip_existing,
                     "with -O: leave outputs that exist (resume a batch)");
    add_force_option(command, force);
}

std::vector<BatchJob> plan_batch(const BatchOptions& o, const std::string& suffix,
                                 size_t& skipped) {
    skipped = 0;
    if (!o.output.empty() && !o.output_dir.empty())
        throw std::runtime_error("give either -o FILE (one input) or -O DIR, not both");
    if (o.output_needed && o.output.empty() && o.output_dir.empty())
        throw std::runtime_error(
            fmt::format("{}: give either -o FILE (one input) or -O DIR", o.command));
    // (input, its output's path below DIR without the suffix)
    std::vector<std::pair<fs::path, fs::path>> found;
    for (const fs::path given : o.inputs) check_input(given, true);
    for (const fs::path given : o.inputs) {
        std::error_code error;
        if (!fs::is_directory(given, error)) {
            found.emplace_back(given, given.stem());
            continue;
        }
        std::vector<fs::path> files;
        for (auto it = fs::recursive_directory_iterator(
                 given, fs::directory_options::skip_permission_denied, error);
             it != fs::recursive_directory_iterator(); it.increment(error)) {
            if (error) break;
            if (it->is_regular_file() && is_sound_file(it->path()) &&
                it->path().filename().string()[0] != '.')
                files.push_back(it->path());
        }
        std::sort(files.begin(), files.end());
        if (files.empty())
            throw std::runtime_error(
                fmt::format("{}: a directory with no sound files in it", given.string()));
        for (const auto& file : files) {
            const fs::path relative = fs::relative(file, given);
            found.emplace_back(file, relative.parent_path() / relative.stem());
        }
    }
    if (o.output_dir.empty() && found.size() > 1)
        throw std::runtime_error(
            fmt::format("-o names one output but {} inputs were given; use -O DIR", found.size()));
    std::vector<BatchJob> jobs;
    std::map<fs::path, fs::path> input_of_output;
    for (const auto& [input, below] : found) {
        if (o.output_dir.empty()) {
            if (!is_stdout(o.output)) check_output(input, o.output, o.force);
            jobs.push_back({input, o.output});  // as the command reads -o: "" or "-" may be stdout
            continue;
        }
        const fs::path output = fs::path(o.output_dir) / (below.string() + suffix);
        if (const auto [it, added] = input_of_output.emplace(output, input); !added)
            throw std::runtime_error(fmt::format("{}: both {} and {} would write it",
                                                 output.string(), it->second.string(),
                                                 input.string()));
        std::error_code error;
        if (o.skip_existing && fs::exists(output, error)) {
            ++skipped;
            continue;
        }
        if (fs::is_directory(output.parent_path(), error))
            check_output(input, output, o.force);
        else
            refuse_overwriting_input(input, output);  // made below: it holds nothing yet
        jobs.push_back({input, output});
    }
    if (skipped > 0) note(fmt::format("{} output(s) exist: skipped (--skip-existing)", skipped));
    return jobs;
}

void run_jobs(const BatchOptions& o, const std::vector<BatchJob>& jobs, const JobTask& one,
              const std::function<int64_t()>& total_frames) {
    for (const BatchJob& job : jobs)
        if (std::error_code error; !job.output.empty() && job.output.has_parent_path() &&
                                   !fs::is_directory(job.output.parent_path()) &&
                                   !fs::create_directories(job.output.parent_path(), error) &&
                                   error)
            throw std::runtime_error(fmt::format("{}: cannot create the output directory: {}",
                                                 job.output.parent_path().string(),
                                                 error.message()));
    if (jobs.size() == 1 && !total_frames) {
        if (const std::string line = one(jobs[0], [](int64_t) {}); !line.empty()) note(line);
        return;
    }
    std::vector<std::string> lines(jobs.size());
    // Each worker writes through one tracked temporary file.
    const std::vector<std::exception_ptr> errors = run_batch(
        jobs.size(), std::min(o.jobs, kMaxTrackedTemporaries),
        total_frames ? total_frames : std::function<int64_t()>([] { return int64_t{0}; }),
        jobs.size() == 1 ? o.command : fmt::format("{} {} files", o.command, jobs.size()),
        [&](size_t i, const AddFrames& add_frames) { lines[i] = one(jobs[i], add_frames); });
    for (size_t i = 0; i < jobs.size(); ++i)
        if (!errors[i] && !lines[i].empty()) note(lines[i]);
    if (jobs.size() == 1 && errors[0]) std::rethrow_exception(errors[0]);
    report_failures(o.command, errors);
}

void report_failures(const std::string& label, const std::vector<std::exception_ptr>& errors) {
    size_t failed = 0;
    for (const std::exception_ptr& error : errors) {
        if (!error) continue;
        ++failed;
        try {
            std::rethrow_exception(error);
        } catch (const std::exception& e) {
            std::cerr << "tactus: error: " << e.what() << '\n';
        }
    }
    if (failed > 0)
        throw std::runtime_error(fmt::format("{}: {} of {} files failed, the others were written",
                                             label, failed, errors.size()));
}

}  // namespace tactus::cli
