// The accuracy-versus-time report: every kernel and knob of glint with its error against an
// exact reference and its time per call, measured with Google Benchmark in the same run.
// Prints markdown; with --docs DIR also writes the tables, CSVs and plots into DIR. With --only,
// the sections' rows replace theirs (by the first column) in DIR's accuracy_vs_time.csv.
//
//   glint_report [--docs DIR] [--min-time SECONDS] [--only core|binomial|grid|ibl|microstructure|scratch|ndf_map|bin_map|lobe_tree]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "report.hpp"

int main(int argc, char** argv) {
    std::string docs, only;
    double min_time = 0.05;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--docs") && i + 1 < argc) docs = argv[++i];
        else if (!std::strcmp(argv[i], "--min-time") && i + 1 < argc) min_time = std::atof(argv[++i]);
        else if (!std::strcmp(argv[i], "--only") && i + 1 < argc) only = argv[++i];
        else {
            std::fprintf(stderr, "usage: %s [--docs DIR] [--min-time SECONDS] [--only core|binomial|grid|ibl|microstructure|scratch|ndf_map|bin_map|lobe_tree]\n", argv[0]);
            return 2;
        }
    }
    std::vector<glint_report::section> sections;
    if (only.empty() || only == "core") sections.push_back(glint_report::core_section(min_time));
    if (only.empty() || only == "binomial") sections.push_back(glint_report::binomial_section(min_time));
    if (only.empty() || only == "grid") sections.push_back(glint_report::grid_section(min_time));
#ifdef GLINT_REPORT_IBL
    if (only.empty() || only == "ibl") sections.push_back(glint_report::ibl_section(min_time));
#endif
    if (only.empty() || only == "microstructure") sections.push_back(glint_report::microstructure_section(min_time));
    if (only.empty() || only == "scratch") sections.push_back(glint_report::scratch_section(min_time));
    if (only.empty() || only == "ndf_map") sections.push_back(glint_report::ndf_map_section(min_time));
    if (only.empty() || only == "bin_map") sections.push_back(glint_report::bin_map_section(min_time));
    if (only.empty() || only == "lobe_tree") sections.push_back(glint_report::lobe_tree_section(min_time));
    std::string csv = glint_report::csv_header;
    for (const auto& s : sections) {
        std::fputs(s.markdown.c_str(), stdout);
        csv += s.csv_rows;
    }
    if (docs.empty()) return 0;
    auto write = [&](const std::string& name, const std::string& content) {
        std::ofstream out(docs + "/" + name);
        out << content;
        if (!out) {
            std::fprintf(stderr, "glint_report: cannot write %s/%s\n", docs.c_str(), name.c_str());
            std::exit(1);
        }
        std::printf("wrote %s/%s\n", docs.c_str(), name.c_str());
    };
    if (only.empty()) {
        write("accuracy_vs_time.csv", csv);
    } else {
        // The rows of the sections run replace those with the same first column, where those were.
        const auto key = [](const std::string& line) { return line.substr(0, line.find(',')); };
        std::set<std::string> keys;
        std::string rows;
        for (const auto& s : sections) rows += s.csv_rows;
        std::istringstream fresh(rows);
        for (std::string line; std::getline(fresh, line);) keys.insert(key(line));
        std::ifstream in(docs + "/accuracy_vs_time.csv");
        std::string merged, line;
        bool placed = false;
        if (std::getline(in, line)) merged = line + "\n";
        else merged = glint_report::csv_header;
        while (std::getline(in, line)) {
            if (!keys.count(key(line))) merged += line + "\n";
            else if (!placed) merged += rows, placed = true;
        }
        if (!placed) merged += rows;
        write("accuracy_vs_time.csv", merged);
    }
    for (const auto& s : sections)
        for (const auto& [name, content] : s.files) write(name, content);
    return 0;
}
