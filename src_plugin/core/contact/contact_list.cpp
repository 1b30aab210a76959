#include "core/contact/contact_list.h"

#include <algorithm>

namespace wiregrain {

const char* contact_kind_name(ContactKind kind) {
  switch (kind) {
    case ContactKind::wire_wire: return "wire_wire";
    case ContactKind::wire_wall: return "wire_wall";
    case ContactKind::wire_grain: return "wire_grain";
    case ContactKind::grain_grain: return "grain_grain";
    case ContactKind::grain_wall: return "grain_wall";
  }
  return "unknown";
}

bool contact_kind_from_name(const std::string& name, ContactKind& kind) {
  for (int k = 0; k < kContactKindCount; k++)
    if (name == contact_kind_name(ContactKind(k))) {
      kind = ContactKind(k);
      return true;
    }
  return false;
}

void ContactSummary::merge(const ContactSummary& other) {
  contacts += other.contacts;
  points += other.points;
  max_overlap = std::max(max_overlap, other.max_overlap);
  normal_force_sum += other.normal_force_sum;
  evaluations += other.evaluations;
}

ContactSummary summarize(const ContactList& list, ContactKind kind) {
  ContactSummary s;
  for (const ContactRecord& r : list.records()) {
    if (r.kind != kind) continue;
    s.points++;
    if (r.status != ContactStatus::open) s.contacts++;
    s.max_overlap = std::max(s.max_overlap, r.overlap);
    s.normal_force_sum += r.force.dot(r.normal);
  }
  s.evaluations = list.evaluations();
  return s;
}

double coordination_number(long contacts, long members) {
  return members > 0 ? double(contacts) / double(members) : 0.0;
}

}  // namespace wiregrain
