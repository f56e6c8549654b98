// tokenizer.h - the text of a MoorDyn v2 deck as the readers of deck/ see it: rows of tokens (MoorDyn's
// '#' comments dropped) grouped by section, the fields of a row read as numbers with the first failure
// kept, and the "line <n>: <what>" convention of every message. Internal to deck/ (the public header
// is deck/line_file.h).
#pragma once

#include <cmath>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace uc {
namespace deck {

// ------------------------------------------------------------------------------------------- text
struct Row {
    int number = 0;                        // 1-based line of the file
    std::vector<std::string_view> tokens;  // up to the first token holding '#', MoorDyn's comment mark
};

// The lines of a text ("\n", "\r\n" or "\r" ends a line).
std::vector<std::string_view> split_lines(std::string_view text);

// The blank-separated tokens of a line, up to the first token holding '#' (MoorDyn's comment mark).
std::vector<std::string_view> tokenize(std::string_view line);

std::string upper(std::string_view s);
std::string lower(std::string_view s);

// A token as it may appear in a message: printable, and short.
std::string quoted(std::string_view token);

// A number as the deck spells it (for messages).
std::string shown(std::string_view token);

// "line <row>: <what>": every message about a row of the deck.
std::string at_line(int row, const std::string& what);

// A number in full precision (%.17g), for messages.
std::string number_text(double v);

// A finite number, the whole token (locale-independent, unlike strtod).
std::optional<double> to_number(std::string_view token);

bool is_one_of(const std::string& name, std::initializer_list<const char*> names);

// ------------------------------------------------------------------------------------------- sections
enum class Kind { Options, LineTypes, RodTypes, Bodies, Rods, Points, Lines, Failure, Control, ExternalLoads,
                  SyropeIC, Outputs, Other };

// The section's name in messages ("LINE TYPES").
const char* title(Kind kind);

// Sections whose rows describe objects outside the supported subset, and why (nullptr: supported).
const char* unsupported(Kind kind);

struct Section {
    int header = 0;  // line of its header
    std::vector<Row> rows;
    Row columns;     // a table's line of column names (empty for options and outputs)
};

// The rows of the text by section (indexed by Kind). A header is a line holding "---"; text outside the
// known sections (the front matter, blocks MoorDyn does not read) is skipped, as MoorDyn does. Tables have
// a line of column names and a line of units after the header; options and outputs do not.
bool collect_sections(std::string_view text, std::vector<std::optional<Section>>& sections, std::string& error);

// ------------------------------------------------------------------------------------------- fields
// Reads the fields of one row; the first failure is kept with its line and column name.
class Fields {
public:
    Fields(const Row& row, std::string& error) : row_(row), error_(error) {}

    bool ok() const { return ok_; }
    bool fail(const std::string& what) {
        if (ok_) error_ = at_line(row_.number, what);
        ok_ = false;
        return false;
    }
    std::string_view token(size_t i) const { return i < row_.tokens.size() ? row_.tokens[i] : std::string_view(); }

    // A finite number in [lo, hi] (bounds in the message as the column's rule).
    double number(size_t i, const char* column, double lo = -HUGE_VAL, double hi = HUGE_VAL, const char* rule = nullptr) {
        if (!ok_) return 0.0;
        const std::optional<double> v = to_number(token(i));
        if (!v) {
            fail(std::string(column) + " " + quoted(token(i)) + " is not a number");
            return 0.0;
        }
        if (*v < lo || *v > hi) {
            fail(std::string(column) + " = " + shown(token(i)) + ": " + (rule ? rule : "out of range"));
            return 0.0;
        }
        return *v;
    }
    double non_negative(size_t i, const char* column) { return number(i, column, 0.0, HUGE_VAL, "must not be negative"); }
    double positive(size_t i, const char* column) {
        const double v = number(i, column, 0.0, HUGE_VAL, "must be positive");
        if (ok_ && !(v > 0.0)) fail(std::string(column) + " = " + shown(token(i)) + ": must be positive");
        return v;
    }
    // A whole number in [lo, hi] ("20" or "20.0", as MoorDyn's atoi reads the former).
    int integer(size_t i, const char* column, int lo, int hi, const char* rule) {
        const double v = number(i, column);
        if (!ok_) return 0;
        if (v != std::floor(v)) {
            fail(std::string(column) + " " + quoted(token(i)) + " is not a whole number");
            return 0;
        }
        if (v < lo || v > hi) {
            fail(std::string(column) + " = " + shown(token(i)) + ": " + rule);
            return 0;
        }
        return static_cast<int>(v);
    }

private:
    const Row& row_;
    std::string& error_;
    bool ok_ = true;
};

// The row's first field, its ID: 1, 2, 3, ... in the order of the section's rows (`what`: "point",
// "line", "body"). False (the error set) where it is not.
bool read_id(Fields& f, const char* what, int expectedId, int& id);

}  // namespace deck
}  // namespace uc
