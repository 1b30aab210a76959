// Contact lists: what every contact style publishes after its force or solve call, and
// the observables computed from them (counts, overlaps, coordination numbers). Outputs
// (computes, dumps) read contacts only through this, never through a style's internals.
//
// One record per contact (per contact point for NSCD manifolds). Identities are atom tags:
// a wire segment is named by the tag of its first bead (the bead whose `next` link starts
// the segment), a grain by its tag, a wall by −(index + 1) in its style's wall list.
// Each contact is published by exactly one MPI rank, so sums over ranks count it once.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

namespace wiregrain {

enum class ContactKind { wire_wire = 0, wire_wall = 1, wire_grain = 2, grain_grain = 3, grain_wall = 4 };
constexpr int kContactKindCount = 5;
const char* contact_kind_name(ContactKind kind);
// The kind named `name` (a contact_kind_name); false when no kind has that name.
bool contact_kind_from_name(const std::string& name, ContactKind& kind);

// open: no force (an NSCD point inside the activation distance that stayed apart);
// stick: tangential force inside the Coulomb cone; slide: on the cone.
enum class ContactStatus { open = 0, stick = 1, slide = 2 };

struct ContactRecord {
  ContactKind kind = ContactKind::wire_wire;
  long a = 0, b = 0;                                    // identities (see above)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      // world frame
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();    // unit, from a to b
  Eigen::Vector3d force = Eigen::Vector3d::Zero();      // on b; a gets −force (NSCD: impulse / h)
  double overlap = 0.0;  // penetration depth at the evaluation (> 0 overlapping; NSCD: −gap at the step start)
  ContactStatus status = ContactStatus::stick;
};

class ContactList {
 public:
  void clear() {
    records_.clear();
    evaluations_ = 0;
  }
  void add(const ContactRecord& record) { records_.push_back(record); }
  const std::vector<ContactRecord>& records() const { return records_; }
  std::size_t size() const { return records_.size(); }
  // exact narrow-phase evaluations done to find these contacts (for benchmarks)
  void count_evaluations(long n) { evaluations_ += n; }
  long evaluations() const { return evaluations_; }

 private:
  std::vector<ContactRecord> records_;
  long evaluations_ = 0;
};

// Counts and extremes of one kind of contact in one list; combine the parts of several
// ranks or styles with merge().
struct ContactSummary {
  long contacts = 0;            // records of the kind that carry force (status ≠ open)
  long points = 0;              // all records of the kind, open ones included
  double max_overlap = 0.0;     // largest overlap among them (0 when none overlaps)
  double normal_force_sum = 0.0;  // Σ force·normal
  long evaluations = 0;
  void merge(const ContactSummary& other);
};
ContactSummary summarize(const ContactList& list, ContactKind kind);

// Mean number of contacts per member: contacts / members (0 when members = 0), e.g. the
// paper's wire–grain coordination z_wpc = (wire–grain contacts) / (wire segments).
double coordination_number(long contacts, long members);

}  // namespace wiregrain
