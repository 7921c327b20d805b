#pragma once
// simcheck's report, for people (text: the first line names the first wrong
// step as "step N: ...", or "shape: ...") and for graders' scripts (--json).

#include "judge.hpp"

#include <cstdio>
#include <string>

namespace simcheck {

struct ReportContext {
    std::string output_name;
    std::string rules;  // "the step rules", "the step rules with 3 substeps", "continuous-time hard disks"
};

void write_text_report(std::FILE* out, const Judgement& judgement, const ReportContext& context);
void write_json_report(std::FILE* out, const Judgement& judgement, const ReportContext& context);
// A JSON string literal of `text`, escaped.
std::string json_string(const std::string& text);

// For exit status 2 with --json: the same shape, verdict "unreadable".
void write_json_unreadable(std::FILE* out, const std::string& message);

}  // namespace simcheck
