// Reads the project's Markdown documents the way readme_test checks them: the ```sh blocks a
// reader would type (with the `<!-- check: ... -->` lines that test their numbers), the links,
// and the headings links can point at.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace radiant::test {

/// A ```sh block: what a reader types, and the shell checks written after it.
struct ShellBlock {
    int line = 0;                     ///< 1-based line of the opening fence
    std::string code;                 ///< the block's text, without the fences
    std::vector<std::string> checks;  ///< `<!-- check: CMD -->` lines before the next block
};

/// A Markdown link `[text](target)` outside code.
struct DocLink {
    int line = 0;
    std::string target;
};

/// What a document holds, and what in it breaks the rules readme_test enforces.
struct MarkdownDoc {
    std::vector<ShellBlock> blocks;
    std::vector<DocLink> links;
    std::set<std::string> anchors;  ///< GitHub's anchors of the headings
    std::vector<std::string> problems;
};

/// GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens (non-ASCII
/// bytes are kept, as GitHub keeps letters such as ρ).
inline std::string heading_anchor(const std::string& heading) {
    std::string anchor;
    for (const char c : heading) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x80 || std::isalnum(u) || c == '-' || c == '_') {
            anchor += static_cast<char>(u < 0x80 ? std::tolower(u) : u);
        } else if (c == ' ') {
            anchor += '-';
        }
    }
    return anchor;
}

namespace markdown_detail {

inline std::string trim(const std::string& s) {
    const std::size_t b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    const std::size_t e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

/// Does an indented line outside a fence look like a command a reader would type?
inline bool looks_like_command(const std::string& line) {
    if (line.rfind("    ", 0) != 0) return false;
    const std::string t = trim(line);
    for (const char* start : {"build/bin/", "scripts/", "curl ", "cmake ", "ctest ", "radiant "}) {
        if (t.rfind(start, 0) == 0) return true;
    }
    return false;
}

/// The `](target)` links of one line outside code spans.
inline void collect_links(const std::string& line, int number, std::vector<DocLink>& links) {
    bool in_code = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (line[i] == '`') in_code = !in_code;
        if (in_code || line.compare(i, 2, "](") != 0) continue;
        const std::size_t end = line.find(')', i + 2);
        if (end == std::string::npos) continue;
        links.push_back({number, line.substr(i + 2, end - i - 2)});
        i = end;
    }
}

}  // namespace markdown_detail

/// Splits `text` into what readme_test runs and checks. Commands go in ```sh blocks only:
/// a fence marked bash, shell or console, an unmarked fence, or an indented line that starts
/// like a command is a problem, so nothing shown as a command escapes the test.
inline MarkdownDoc parse_markdown(const std::string& text) {
    using namespace markdown_detail;
    MarkdownDoc doc;
    std::istringstream in(text);
    std::string line;
    int number = 0;
    bool in_fence = false;
    bool in_sh = false;
    bool after_blank = true;
    while (std::getline(in, line)) {
        ++number;
        const std::string t = trim(line);
        if (t.rfind("```", 0) == 0) {
            if (in_fence) {
                in_fence = in_sh = false;
            } else {
                in_fence = true;
                const std::string lang = trim(t.substr(3));
                in_sh = lang == "sh";
                if (in_sh) doc.blocks.push_back({number, {}, {}});
                if (lang.empty() || lang == "bash" || lang == "shell" || lang == "console") {
                    doc.problems.push_back("line " + std::to_string(number) + ": a fence marked '" +
                                           lang +
                                           "': use ```sh for commands (they run in "
                                           "readme_test) or ```text for other text");
                }
            }
            continue;
        }
        if (in_fence) {
            if (in_sh) doc.blocks.back().code += line + "\n";
            continue;
        }
        const std::string check_open = "<!-- check:";
        if (t.rfind(check_open, 0) == 0) {
            const std::size_t close = t.rfind("-->");
            if (doc.blocks.empty() || close == std::string::npos) {
                doc.problems.push_back("line " + std::to_string(number) +
                                       ": a check needs a ```sh block before it and a closing -->");
            } else {
                doc.blocks.back().checks.push_back(
                    trim(t.substr(check_open.size(), close - check_open.size())));
            }
            continue;
        }
        if (after_blank && looks_like_command(line)) {
            doc.problems.push_back("line " + std::to_string(number) +
                                   ": an indented command; put it in a ```sh block: " + t);
        }
        after_blank = t.empty() || (after_blank && looks_like_command(line));
        if (t.rfind('#', 0) == 0) {
            const std::size_t text_start = t.find_first_not_of('#');
            if (text_start != std::string::npos && t[text_start] == ' ') {
                doc.anchors.insert(heading_anchor(trim(t.substr(text_start))));
            }
        }
        collect_links(line, number, doc.links);
    }
    if (in_fence) doc.problems.push_back("a fence is not closed");
    return doc;
}

/// README.md and every docs/*.md, relative to the source directory, sorted.
inline std::vector<std::string> project_documents(const std::filesystem::path& source_dir) {
    std::vector<std::string> docs = {"README.md"};
    for (const auto& entry : std::filesystem::directory_iterator(source_dir / "docs")) {
        if (entry.path().extension() == ".md") {
            docs.push_back("docs/" + entry.path().filename().string());
        }
    }
    std::sort(docs.begin() + 1, docs.end());
    return docs;
}

}  // namespace radiant::test
