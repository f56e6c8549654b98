// failures.cpp - the FAILURE section of a MoorDyn v2 deck as MoorDyn-F writes it (docs/line_failure.md):
// at which point which lines detach, by time or by tension.
#include "deck/tables.h"

#include <algorithm>

namespace uc {
namespace deck {

bool read_failure(const Row& row, int expectedId, const std::vector<Point>& points, const std::vector<Line>& lines,
                  Failure& out, std::string& error) {
    Fields f(row, error);
    if (row.tokens.size() < 5) {
        return f.fail("a failure has the fields ID Point Line(s) FailTime FailTen; this row has " +
                      std::to_string(row.tokens.size()));
    }
    if (!read_id(f, "failure", expectedId, out.id)) return false;
    if (!read_attachment(f, row.tokens[1], "Point", static_cast<int>(points.size()), out.point)) return false;
    // Line(s): line IDs separated by commas ("1" or "1,2")
    std::string_view list = row.tokens[2];
    while (true) {
        const size_t comma = list.find(',');
        const std::string_view word = list.substr(0, comma);
        const auto id = to_number(word);
        if (!id || *id != static_cast<double>(static_cast<int>(*id))) {
            return f.fail("Line(s) " + quoted(row.tokens[2]) + ": " + quoted(word) +
                          " is not a line ID (line IDs separated by commas, such as 1,2)");
        }
        const int k = static_cast<int>(*id);
        if (k < 1 || k > static_cast<int>(lines.size())) {
            return f.fail("Line(s) " + quoted(row.tokens[2]) + ": there is no line " + std::to_string(k) +
                          " (the LINES table has " + std::to_string(lines.size()) + ")");
        }
        if (std::find(out.lines.begin(), out.lines.end(), k - 1) != out.lines.end()) {
            return f.fail("Line(s) " + quoted(row.tokens[2]) + ": line " + std::to_string(k) + " is listed twice");
        }
        const Line& l = lines[k - 1];
        if (l.end[0] != out.point && l.end[1] != out.point) {
            return f.fail("Line(s) " + quoted(row.tokens[2]) + ": line " + std::to_string(k) + " is not attached to point " +
                          std::to_string(points[out.point].id) + " (its ends are points " +
                          std::to_string(points[l.end[0]].id) + " and " + std::to_string(points[l.end[1]].id) + ")");
        }
        out.lines.push_back(k - 1);
        if (comma == std::string_view::npos) break;
        list = list.substr(comma + 1);
    }
    out.time = f.non_negative(3, "FailTime");
    out.tension = f.non_negative(4, "FailTen");
    if (f.ok() && out.time == 0.0 && out.tension == 0.0) {
        return f.fail("FailTime and FailTen are both 0: the failure would never happen (give a time in s, a tension "
                      "in N, or both: the first reached breaks)");
    }
    out.row = row.number;
    return f.ok();
}

}  // namespace deck
}  // namespace uc
