// grid_text.cpp - see grid_text.h.
#include "terms/grid_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace uc {

std::string number_text(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        if (end == text.size()) break;
        start = end + 1;
    }
    return lines;
}

bool numbers(std::string_view line, int number, std::vector<double>& out, std::string& error) {
    out.clear();
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == ',')) ++i;
        size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != ',') ++j;
        if (j == i) break;
        const std::string token(line.substr(i, j - i));
        char* end = nullptr;
        const double v = std::strtod(token.c_str(), &end);
        if (end == token.c_str() || *end != '\0' || !std::isfinite(v)) {
            error = "line " + std::to_string(number) + ": '" + token + "' is not a number";
            return false;
        }
        out.push_back(v);
        i = j;
    }
    return true;
}

bool ascending(const std::vector<double>& axis, const char* name, int number, std::string& error) {
    for (size_t k = 1; k < axis.size(); ++k) {
        if (!(axis[k] > axis[k - 1])) {
            error = "line " + std::to_string(number) + ": " + name + " = " + number_text(axis[k]) + " after " +
                    number_text(axis[k - 1]) + ": the values must increase (MoorDyn interpolates between them in "
                    "that order)";
            return false;
        }
    }
    return true;
}

Bracket bracket(const std::vector<double>& axis, double v) {
    Bracket b;
    const int n = static_cast<int>(axis.size());
    if (n == 1) return b;
    if (!(v > axis.front())) {
        b.hi = 1;
        b.outside = v < axis.front();
        return b;
    }
    if (!(v < axis.back())) {
        b.lo = n - 2;
        b.hi = n - 1;
        b.f = 1.0;
        b.outside = v > axis.back();
        return b;
    }
    b.hi = static_cast<int>(std::lower_bound(axis.begin(), axis.end(), v) - axis.begin());
    b.lo = b.hi - 1;
    const double span = axis[b.hi] - axis[b.lo];
    b.f = (v - axis[b.lo]) / span;
    b.slope = 1.0 / span;
    return b;
}

}  // namespace uc
