// deck_mutation.h - random truncations and mutations of a deck's text (a fixed seed gives the same ones),
// for the readers' robustness tests: truncate, replace or insert a byte, delete a run, duplicate text, swap
// two lines; one to four edits.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>

inline std::string mutate_deck(std::string deck, std::mt19937& rng) {
    auto pick = [&](size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
    static const char kBytes[] = {'\0', '#', '-', '|', ' ', '\t', '\n', '\r', '0', '9', '.', 'e', '+', 'x', '\xff'};
    const int edits = 1 + static_cast<int>(pick(4));
    for (int k = 0; k < edits && !deck.empty(); ++k) {
        const size_t at = pick(deck.size());
        switch (pick(6)) {
            case 0: deck.resize(at); break;                                         // truncate
            case 1: deck[at] = kBytes[pick(sizeof kBytes)]; break;                  // replace a byte
            case 2: deck.erase(at, 1 + pick(20)); break;                            // delete a run
            case 3: deck.insert(at, deck.substr(pick(deck.size()), 1 + pick(80))); break;  // duplicate text
            case 4: deck.insert(at, 1, static_cast<char>(pick(256))); break;        // insert any byte
            default: {                                                              // swap two lines
                const size_t a = deck.rfind('\n', at), b = deck.find('\n', at);
                if (a != std::string::npos && b != std::string::npos && b + 1 < deck.size()) {
                    const size_t c = deck.find('\n', b + 1);
                    if (c != std::string::npos) {
                        const std::string first = deck.substr(a + 1, b - a), second = deck.substr(b + 1, c - b);
                        deck.replace(a + 1, c - a, second + first);
                    }
                }
            }
        }
    }
    return deck;
}

// A refusal "line <n>: ..." names a line of the deck (1 <= n <= its lines): true, or false for another
// message (which the caller judges) with *named false; false with *named true for a line out of the deck.
inline bool names_a_line_of(const std::string& message, const std::string& deck, bool* named) {
    *named = message.rfind("line ", 0) == 0;
    if (!*named) return false;
    const int line = std::atoi(message.c_str() + 5);
    const int lines = 1 + static_cast<int>(std::count(deck.begin(), deck.end(), '\n') +
                                           std::count(deck.begin(), deck.end(), '\r'));
    return line >= 1 && line <= lines;
}
