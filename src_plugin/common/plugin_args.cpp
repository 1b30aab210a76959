#include "plugin_args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <algorithm>
#include <utility>

#include <mpi.h>

#include "atom.h"
#include "error.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"

namespace wiregrain_lmp {

namespace {
std::string make_prefix(const std::string& kind, const std::string& style, const std::string& id) {
  if (id.empty()) return kind + " " + style + ": ";
  return kind + " " + style + " (id " + id + "): ";
}
}  // namespace

KeywordList concat(KeywordList a, const KeywordList& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

StyleArgs::StyleArgs(LAMMPS_NS::Error* error, std::string kind, std::string style,
                     std::string id, int narg, char** arg, int first, KeywordList keywords)
    : error_(error),
      prefix_(make_prefix(kind, style, id)),
      narg_(narg),
      arg_(arg),
      pos_(first),
      keywords_(std::move(keywords)) {}

std::string StyleArgs::next_word() {
  if (pos_ >= narg_) fail("missing argument at the end of the line");
  return std::string(arg_[pos_++]);
}

std::string StyleArgs::next_keyword() {
  const std::string word = next_word();
  if (std::find(keywords_.begin(), keywords_.end(), word) == keywords_.end()) unknown_keyword(word);
  return word;
}

std::string StyleArgs::value_word(const std::string& keyword) {
  if (pos_ >= narg_) fail("missing value after '" + keyword + "'");
  return std::string(arg_[pos_++]);
}

bool parse_finite_number(const char* word, double& value) {
  char* end = nullptr;
  errno = 0;
  value = std::strtod(word, &end);
  return end != word && *end == '\0' && errno != ERANGE && std::isfinite(value);
}

double StyleArgs::value_double(const std::string& keyword) {
  const std::string word = value_word(keyword);
  double v = 0.0;
  if (!parse_finite_number(word.c_str(), v))
    fail("value of '" + keyword + "' must be a finite number, got '" + word + "'");
  return v;
}

long StyleArgs::value_int(const std::string& keyword) {
  const std::string word = value_word(keyword);
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(word.c_str(), &end, 10);
  if (end == word.c_str() || *end != '\0' || errno == ERANGE)
    fail("value of '" + keyword + "' must be an integer, got '" + word + "'");
  return v;
}

long StyleArgs::value_int_in_range(const std::string& keyword, long lo, long hi, const std::string& label) {
  const long v = value_int(keyword);
  const std::string name = label.empty() ? "'" + keyword + "'" : label;
  if (v < lo) fail("value of " + name + " must be >= " + std::to_string(lo) + ", got " + std::to_string(v));
  if (v > hi) fail("value of " + name + " must be <= " + std::to_string(hi) + ", got " + std::to_string(v));
  return v;
}

double StyleArgs::value_positive(const std::string& keyword) {
  const double v = value_double(keyword);
  if (!(v > 0.0)) fail("value of '" + keyword + "' must be > 0, got " + arg_[pos_ - 1]);
  return v;
}

double StyleArgs::value_nonnegative(const std::string& keyword) {
  const double v = value_double(keyword);
  if (!(v >= 0.0)) fail("value of '" + keyword + "' must be >= 0, got " + arg_[pos_ - 1]);
  return v;
}

double StyleArgs::value_in_range(const std::string& keyword, double lo, double hi, const std::string& range_text) {
  const double v = value_double(keyword);
  if (!(v >= lo && v <= hi)) fail("value of '" + keyword + "' must be in " + range_text + ", got " + arg_[pos_ - 1]);
  return v;
}

void StyleArgs::unknown_keyword(const std::string& keyword) const {
  if (std::find(keywords_.begin(), keywords_.end(), keyword) != keywords_.end())
    fail("keyword '" + keyword + "' is accepted but not handled (a defect of the plugin: please report it)");
  if (keywords_.empty()) fail("unknown keyword '" + keyword + "'; this style takes no keywords");
  std::string accepted;
  for (const std::string& k : keywords_) accepted += (accepted.empty() ? "" : ", ") + k;
  fail("unknown keyword '" + keyword + "'; accepted: " + accepted);
}

void StyleArgs::fail(const std::string& what) const {
  error_->all(FLERR, (prefix_ + what).c_str());
  std::abort();  // error->all does not return; keeps [[noreturn]] honest
}

void style_error(LAMMPS_NS::Error* error, const std::string& kind, const std::string& style,
                 const std::string& id, const std::string& what) {
  error->all(FLERR, (make_prefix(kind, style, id) + what).c_str());
  std::abort();
}

void ensure_sole_integrator(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix *fix, const std::string &kind,
                            const std::string &style, const std::string &what) {
  LAMMPS_NS::Atom *atom = lmp->atom;
  LAMMPS_NS::Modify *modify = lmp->modify;
  for (int k = 0; k < modify->nfix; k++) {
    LAMMPS_NS::Fix *other = modify->fix[k];
    if (other == fix || !other->time_integrate) continue;
    int local = 0, shared = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & fix->groupbit) && (atom->mask[i] & other->groupbit)) local++;
    MPI_Allreduce(&local, &shared, 1, MPI_INT, MPI_SUM, lmp->world);
    if (shared)
      style_error(lmp->error, kind, style, fix->id,
                  std::to_string(shared) + " " + what + " are also integrated by fix " + other->id + " (" +
                      other->style + ")");
  }
}

}  // namespace wiregrain_lmp
