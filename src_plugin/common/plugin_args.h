// Argument parsing and error messages shared by the plugin's LIGGGHTS styles.
// Every message reads "<kind> <style> (id <ID>): <what>", so a user sees which
// command and which argument are wrong; LIGGGHTS prefixes it with "ERROR: ".
#ifndef WIREGRAIN_PLUGIN_ARGS_H
#define WIREGRAIN_PLUGIN_ARGS_H

#include <initializer_list>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class Error;
class Fix;
class LAMMPS;
}

namespace wiregrain_lmp {

// The optional keywords a style's line accepts, in the order of the keyword table of its
// page in docs/commands/. The list is the style's contract: StyleArgs::next_keyword refuses
// any other word and names these in its message, which the documentation test reads to
// compare each page's table with the code.
using KeywordList = std::vector<std::string>;

// a followed by b, for a style that accepts a shared family of keywords (plugin_material.h)
KeywordList concat(KeywordList a, const KeywordList& b);

class StyleArgs {
 public:
  // kind: "fix", "pair", "compute", ...; style and id as the user gave them (an empty id:
  // messages read "<kind> <style>: ...", for atom styles); keywords: the optional keywords
  // the style accepts (none when empty).
  StyleArgs(LAMMPS_NS::Error* error, std::string kind, std::string style, std::string id,
            int narg, char** arg, int first, KeywordList keywords = {});

  bool done() const { return pos_ >= narg_; }
  // the next word as it is, for a positional argument (a group, a mode, a layout)
  std::string next_word();
  // the next word as an optional keyword: one of the style's keywords, else stops with
  // "unknown keyword 'x'; accepted: a, b, c" (or "...; this style takes no keywords")
  std::string next_keyword();
  // the value following `keyword`; stops with "missing value after 'keyword'"
  std::string value_word(const std::string& keyword);
  double value_double(const std::string& keyword);
  long value_int(const std::string& keyword);
  // value_int in [lo, hi], e.g. "value of 'every' must be >= 1, got 0"; hi defaults to the
  // largest int, so the value fits the int it is stored in ("must be <= 2147483647, got
  // 3000000000" instead of a wrapped negative count). label replaces "'keyword'" in the text.
  long value_int_in_range(const std::string& keyword, long lo, long hi = 2147483647L,
                          const std::string& label = "");
  // value_double with a domain check, e.g. "value of 'E' must be > 0, got -1"
  double value_positive(const std::string& keyword);
  double value_nonnegative(const std::string& keyword);
  // "value of 'theta' must be in [0.5, 1], got 0.4"; lo and hi given as the user reads them
  double value_in_range(const std::string& keyword, double lo, double hi, const std::string& range_text);

  // the end of a keyword dispatch: a keyword of the list that no branch handled is a defect of
  // the style ("keyword 'x' is accepted but not handled"), any other word an unknown keyword
  [[noreturn]] void unknown_keyword(const std::string& keyword) const;
  const KeywordList& keywords() const { return keywords_; }
  [[noreturn]] void fail(const std::string& what) const;
  const std::string& prefix() const { return prefix_; }

 private:
  LAMMPS_NS::Error* error_;
  std::string prefix_;
  int narg_;
  char** arg_;
  int pos_;
  KeywordList keywords_;
};

// A style's optional keywords with their handlers, one entry per keyword in the order of the
// keyword table of its page in docs/commands/: the KeywordList StyleArgs accepts and the
// dispatch come from the same entries, so they cannot drift apart. Target: what the handlers
// set (the style itself, or a struct of its settings). A handler reads the keyword's values
// from the StyleArgs; it is given the keyword (for its messages, and for a handler shared by
// several keywords). A captureless lambda converts to a Handler:
//     static const KeywordTable<FixFoo> keywords = {
//         {"damping", [](StyleArgs &args, FixFoo &fix, const std::string &key) {
//            fix.damping = args.value_nonnegative(key); }},
//         ...};
//     StyleArgs args(error, "fix", "foo", id, narg, arg, 3, keywords.keywords());
//     keywords.parse(args, *this);
template <class Target>
class KeywordTable {
 public:
  using Handler = void (*)(StyleArgs& args, Target& target, const std::string& keyword);
  struct Entry {
    const char* keyword;
    Handler handle;
  };

  KeywordTable(std::initializer_list<Entry> entries) : entries_(entries) {}

  // the keywords in the table's order, for StyleArgs
  KeywordList keywords() const {
    KeywordList list;
    for (const Entry& e : entries_) list.emplace_back(e.keyword);
    return list;
  }
  bool has(const std::string& keyword) const { return find(keyword) != nullptr; }
  // the keyword's handler; StyleArgs::unknown_keyword for a word the table does not hold
  void dispatch(StyleArgs& args, Target& target, const std::string& keyword) const {
    const Entry* entry = find(keyword);
    if (!entry) args.unknown_keyword(keyword);
    entry->handle(args, target, keyword);
  }
  // every keyword to the end of the line (StyleArgs::next_keyword), each by its handler
  void parse(StyleArgs& args, Target& target) const {
    while (!args.done()) {
      const std::string keyword = args.next_keyword();
      dispatch(args, target, keyword);
    }
  }

 private:
  const Entry* find(const std::string& keyword) const {
    for (const Entry& e : entries_)
      if (keyword == e.keyword) return &e;
    return nullptr;
  }
  std::vector<Entry> entries_;
};

// The whole word as a finite double (no trailing characters, no inf/nan, no overflow such as
// 1e400); false otherwise. Used for every number read from the input and data files.
bool parse_finite_number(const char* word, double& value);

// "<kind> <style> (id <ID>): <what>" through error->all, for checks outside parsing.
[[noreturn]] void style_error(LAMMPS_NS::Error* error, const std::string& kind,
                              const std::string& style, const std::string& id,
                              const std::string& what);

// Stops with "<kind> <style> (id ID): N atoms are also integrated by fix X (style)" when
// another time-integrating fix acts on atoms of this fix's group.
void ensure_sole_integrator(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix *fix, const std::string &kind,
                            const std::string &style, const std::string &what);

}  // namespace wiregrain_lmp

#endif
