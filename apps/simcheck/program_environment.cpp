#include "program_environment.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

extern char** environ;

namespace simcheck {
namespace {

// Whole names, then prefixes: the locale, the temporary directory, where
// libraries are found; OpenMP's settings (GCC's, LLVM's), MPI's runtimes'
// (OpenMPI, PMIx, PRRTE, MPICH and Intel MPI's Hydra), the sanitizers'.
constexpr std::string_view default_names[] = {"PATH", "LANG", "LANGUAGE", "TZ", "TMPDIR", "LD_LIBRARY_PATH"};
constexpr std::string_view default_prefixes[] = {"LC_",   "OMP_",  "GOMP_",  "KMP_",   "OMPI_",
                                                 "PMIX_", "PRTE_", "MPICH_", "HYDRA_", "I_MPI_"};
constexpr std::string_view sanitizer_suffix = "SAN_OPTIONS";  // ASAN_, UBSAN_, LSAN_, TSAN_, MSAN_

bool valid_name(std::string_view name) {
    if (name.empty() || (name[0] >= '0' && name[0] <= '9')) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
}

std::string_view name_of(std::string_view entry) { return entry.substr(0, entry.find('=')); }

// Whether `name` is a variable the program gets by default.
bool passed_by_default(const std::string& name) {
    const std::string_view n = name;
    if (std::find(std::begin(default_names), std::end(default_names), n) != std::end(default_names)) return true;
    for (const std::string_view prefix : default_prefixes)
        if (n.substr(0, prefix.size()) == prefix) return true;
    return n.size() > sanitizer_suffix.size() && n.substr(n.size() - sanitizer_suffix.size()) == sanitizer_suffix;
}

}  // namespace

void add_environment_option(const std::string& argument, EnvironmentChoice& choice) {
    const std::size_t equals = argument.find('=');
    const std::string name = argument.substr(0, equals);
    if (!valid_name(name))
        throw std::invalid_argument("\"" + argument + "\" is not NAME or NAME=VALUE (letters, digits and _)");
    if (equals != std::string::npos) {
        choice.assigned.push_back(argument);
    } else {
        if (!std::getenv(name.c_str())) throw std::invalid_argument(name + " is not set here; give NAME=VALUE");
        choice.passed.push_back(name);
    }
}

std::vector<std::string> program_environment(const EnvironmentChoice& choice, const std::string& home) {
    std::vector<std::string> entries;
    for (char** entry = environ; *entry; ++entry) {
        const std::string text = *entry;
        const std::string name(name_of(text));
        const bool passed = std::find(choice.passed.begin(), choice.passed.end(), name) != choice.passed.end();
        if (choice.full || passed || (name != "HOME" && passed_by_default(name))) entries.push_back(text);
    }
    const bool home_passed = std::find(choice.passed.begin(), choice.passed.end(), "HOME") != choice.passed.end();
    if (!choice.full && !home_passed) entries.push_back("HOME=" + home);
    // Assigned last, each replacing what came before under its name.
    for (const std::string& assignment : choice.assigned) {
        const std::string_view name = name_of(assignment);
        entries.erase(std::remove_if(entries.begin(), entries.end(),
                                     [&](const std::string& entry) { return name_of(entry) == name; }),
                      entries.end());
        entries.push_back(assignment);
    }
    return entries;
}

}  // namespace simcheck
