// tokenizer.cpp - rows, sections and fields of a MoorDyn v2 deck's text (deck/tokenizer.h).
#include "deck/tokenizer.h"

#include <cctype>
#include <charconv>
#include <cstdio>

namespace uc {
namespace deck {

std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t begin = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\n' && text[i] != '\r') continue;
        lines.push_back(text.substr(begin, i - begin));
        if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        begin = i + 1;
    }
    if (begin < text.size()) lines.push_back(text.substr(begin));
    return lines;
}

namespace {
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
}  // namespace

std::vector<std::string_view> tokenize(std::string_view line) {
    std::vector<std::string_view> tokens;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) ++i;
        const size_t begin = i;
        while (i < line.size() && !is_blank(line[i])) ++i;
        if (i == begin) break;
        const std::string_view token = line.substr(begin, i - begin);
        if (token.find('#') != std::string_view::npos) break;
        tokens.push_back(token);
    }
    return tokens;
}

std::string upper(std::string_view s) {
    std::string u(s);
    for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return u;
}

std::string lower(std::string_view s) {
    std::string u(s);
    for (char& c : u) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return u;
}

std::string quoted(std::string_view token) {
    std::string q = "'";
    for (size_t i = 0; i < token.size() && i < 40; ++i) {
        const unsigned char c = static_cast<unsigned char>(token[i]);
        q += std::isprint(c) ? static_cast<char>(c) : '?';
    }
    if (token.size() > 40) q += "...";
    return q + "'";
}

std::string shown(std::string_view token) {
    const std::string q = quoted(token);
    return q.substr(1, q.size() - 2);
}

std::string at_line(int row, const std::string& what) { return "line " + std::to_string(row) + ": " + what; }

std::string number_text(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

std::optional<double> to_number(std::string_view token) {
    if (!token.empty() && token[0] == '+') token.remove_prefix(1);
    double v = 0.0;
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, v);
    if (ec != std::errc() || ptr != end || !std::isfinite(v)) return std::nullopt;
    return v;
}

bool is_one_of(const std::string& name, std::initializer_list<const char*> names) {
    for (const char* n : names) {
        if (name == n) return true;
    }
    return false;
}

namespace {

struct SectionName {
    Kind kind;
    const char* keyword;  // as MoorDyn finds it: in the upper-cased header line
};

// The header words MoorDyn v2 recognizes, more specific first ("LINE TYPES" before "LINES").
constexpr SectionName kSectionNames[] = {
    {Kind::LineTypes, "LINE TYPES"}, {Kind::LineTypes, "LINE DICTIONARY"},
    {Kind::RodTypes, "ROD TYPES"}, {Kind::RodTypes, "ROD DICTIONARY"},
    {Kind::Bodies, "BODIES"}, {Kind::Bodies, "BODY LIST"}, {Kind::Bodies, "BODY PROPERTIES"},
    {Kind::Rods, "RODS"}, {Kind::Rods, "ROD LIST"}, {Kind::Rods, "ROD PROPERTIES"},
    {Kind::Points, "POINTS"}, {Kind::Points, "POINT LIST"}, {Kind::Points, "POINT PROPERTIES"},
    {Kind::Points, "CONNECTION PROPERTIES"}, {Kind::Points, "NODE PROPERTIES"},
    {Kind::Lines, "LINES"}, {Kind::Lines, "LINE LIST"}, {Kind::Lines, "LINE PROPERTIES"},
    {Kind::Options, "OPTIONS"}, {Kind::Failure, "FAILURE"}, {Kind::Control, "CONTROL"},
    {Kind::ExternalLoads, "EXTERNAL LOADS"}, {Kind::SyropeIC, "SYROPE IC"}, {Kind::Outputs, "OUTPUT"},
};

Kind classify_header(std::string_view line) {
    const std::string u = upper(line);
    for (const SectionName& s : kSectionNames) {
        if (u.find(s.keyword) != std::string::npos) return s.kind;
    }
    return Kind::Other;
}

}  // namespace

const char* title(Kind kind) {
    switch (kind) {
        case Kind::Options: return "OPTIONS";
        case Kind::LineTypes: return "LINE TYPES";
        case Kind::RodTypes: return "ROD TYPES";
        case Kind::Bodies: return "BODIES";
        case Kind::Rods: return "RODS";
        case Kind::Points: return "POINTS";
        case Kind::Lines: return "LINES";
        case Kind::Failure: return "FAILURE";
        case Kind::Control: return "CONTROL";
        case Kind::ExternalLoads: return "EXTERNAL LOADS";
        case Kind::SyropeIC: return "SYROPE IC";
        case Kind::Outputs: return "OUTPUTS";
        default: return "?";
    }
}

// Sections whose rows describe objects outside the supported subset, and why.
const char* unsupported(Kind kind) {
    switch (kind) {
        case Kind::Bodies: return "bodies are not supported";
        case Kind::Rods: return "rods are not supported";
        case Kind::Failure: return "line failures are supported in a mooring system's deck only, not on one line (docs/line_failure.md)";
        case Kind::Control: return "line length control is not supported";
        case Kind::ExternalLoads: return "external loads on points, rods and bodies are not supported";
        default: return nullptr;
    }
}

bool collect_sections(std::string_view text, std::vector<std::optional<Section>>& sections, std::string& error) {
    sections.assign(static_cast<size_t>(Kind::Other) + 1, std::nullopt);
    const std::vector<std::string_view> lines = split_lines(text);
    Section* current = nullptr;
    Kind kind = Kind::Other;
    int headerLinesLeft = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        const int number = static_cast<int>(i) + 1;
        if (lines[i].find("---") != std::string_view::npos) {
            if (current && headerLinesLeft > 0) {
                error = at_line(current->header, std::string("the ") + title(kind) +
                                                     " table needs a line of column names and a line of units");
                return false;
            }
            kind = classify_header(lines[i]);
            current = nullptr;
            if (kind == Kind::Other) continue;
            auto& slot = sections[static_cast<size_t>(kind)];
            if (slot) {
                error = at_line(number, std::string("a second ") + title(kind) + " section (the first is at line " +
                                            std::to_string(slot->header) + ")");
                return false;
            }
            slot = Section{number, {}, {}};
            current = &*slot;
            headerLinesLeft = (kind == Kind::Options || kind == Kind::Outputs) ? 0 : 2;
            continue;
        }
        if (current == nullptr) continue;
        if (headerLinesLeft > 0) {
            if (headerLinesLeft == 2) current->columns = Row{number, tokenize(lines[i])};
            --headerLinesLeft;
            continue;
        }
        Row row{number, tokenize(lines[i])};
        if (row.tokens.empty()) continue;
        if (kind == Kind::Outputs && upper(row.tokens[0]) == "END") {
            current = nullptr;  // MoorDyn stops reading outputs at END
            continue;
        }
        current->rows.push_back(std::move(row));
    }
    if (current && headerLinesLeft > 0) {
        error = at_line(current->header,
                        std::string("the ") + title(kind) + " table needs a line of column names and a line of units");
        return false;
    }
    return true;
}

bool read_id(Fields& f, const char* what, int expectedId, int& id) {
    id = f.integer(0, "ID", 1, 1 << 30, "must be positive");
    if (f.ok() && id != expectedId) {
        return f.fail(std::string(what) + " ID " + std::to_string(id) + ": IDs must be 1, 2, 3, ... in order (expected " +
                      std::to_string(expectedId) + ")");
    }
    return f.ok();
}

}  // namespace deck
}  // namespace uc
