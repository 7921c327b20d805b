#include "distinct_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace simcli {

namespace {

// What makes two names one file: the device and inode of an existing
// regular file, else (a file yet to be made) the name made absolute.
struct FileIdentity {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    std::filesystem::path name;

    bool operator==(const FileIdentity& other) const {
        if (exists != other.exists) return false;
        return exists ? device == other.device && inode == other.inode : name == other.name;
    }
};

struct NamedFile {
    std::string option;  // as the message names it
    std::string path;    // empty for standard output
    FileIdentity identity;

    [[nodiscard]] std::string named() const { return path.empty() ? option : option + " " + path; }
};

// Nothing for a device, a pipe or a directory: not a file one run could spoil.
std::optional<FileIdentity> identity_of(const std::string& path) {
    struct stat found {};
    if (stat(path.c_str(), &found) == 0) {
        if (!S_ISREG(found.st_mode)) return std::nullopt;
        return FileIdentity{true, found.st_dev, found.st_ino, {}};
    }
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    return FileIdentity{false, 0, 0, (error ? std::filesystem::path(path) : absolute).lexically_normal()};
}

void add(std::vector<NamedFile>& files, const std::string& option, const std::optional<std::string>& path) {
    if (!path) return;
    if (const std::optional<FileIdentity> identity = identity_of(*path)) files.push_back({option, *path, *identity});
}

}  // namespace

void require_distinct_files(const CliOptions& options) {
    std::vector<NamedFile> written;
    add(written, "-o", options.output_path);
    struct stat output {};
    // Without -o the states go to standard output: a file the shell opened is one of the outputs too.
    if (!options.output_path && fstat(STDOUT_FILENO, &output) == 0 && S_ISREG(output.st_mode))
        written.push_back({"standard output", "", FileIdentity{true, output.st_dev, output.st_ino, {}}});
    add(written, "--checkpoint", options.checkpoint_path);
    add(written, "--trajectory", options.trajectory_path);
    add(written, "--observables", options.observables_path);
    add(written, "--animate", options.animation ? std::optional<std::string>(options.animation->path) : std::nullopt);
    add(written, "--snapshot", options.snapshot_path);
    for (std::size_t a = 0; a < written.size(); ++a) {
        for (std::size_t b = a + 1; b < written.size(); ++b) {
            if (written[a].identity == written[b].identity) {
                throw BadInput(written[a].named() + " and " + written[b].named() +
                               " name the same file: each output needs a file of its own");
            }
        }
    }
    std::vector<NamedFile> read;
    if (options.scene_path != "-") add(read, "the scene file it reads", options.scene_path);
    add(read, "the checkpoint it resumes", options.resume_path);
    for (const NamedFile& input : read) {
        for (const NamedFile& output : written) {
            const bool checkpoint_again = output.option == "--checkpoint" && options.resume_path;
            if (output.identity == input.identity && !checkpoint_again) {
                throw BadInput(output.named() + " names " + input.option + ": it would be replaced");
            }
        }
    }
}

}  // namespace simcli
