// Contact lists and their summaries (core/contact/contact_list.h), on hand-built lists.
#include <gtest/gtest.h>

#include "core/contact/contact_list.h"

using namespace wiregrain;

namespace {
ContactRecord record(ContactKind kind, double overlap, double normal_force, ContactStatus status) {
  ContactRecord r;
  r.kind = kind;
  r.normal = Eigen::Vector3d(0.0, 0.6, 0.8);
  r.force = normal_force * r.normal + Eigen::Vector3d(0.8, 0.0, 0.0) * 0.1;  // tangential part ⟂ n
  r.overlap = overlap;
  r.status = status;
  return r;
}
}  // namespace

TEST(ContactList, SummaryCountsOneKindAndSkipsOpenPointsInTheCount) {
  ContactList list;
  list.add(record(ContactKind::wire_grain, 0.01, 2.0, ContactStatus::stick));
  list.add(record(ContactKind::wire_grain, 0.03, 1.0, ContactStatus::slide));
  list.add(record(ContactKind::wire_grain, -0.02, 0.0, ContactStatus::open));
  list.add(record(ContactKind::wire_wire, 0.5, 7.0, ContactStatus::stick));
  list.count_evaluations(11);
  const ContactSummary s = summarize(list, ContactKind::wire_grain);
  EXPECT_EQ(s.points, 3);
  EXPECT_EQ(s.contacts, 2);
  EXPECT_DOUBLE_EQ(s.max_overlap, 0.03);
  EXPECT_NEAR(s.normal_force_sum, 3.0, 1e-15);
  EXPECT_EQ(s.evaluations, 11);
  const ContactSummary w = summarize(list, ContactKind::wire_wire);
  EXPECT_EQ(w.contacts, 1);
  EXPECT_DOUBLE_EQ(w.max_overlap, 0.5);
  EXPECT_EQ(summarize(list, ContactKind::grain_wall).points, 0);
  EXPECT_EQ(summarize(list, ContactKind::grain_wall).max_overlap, 0.0);
}

TEST(ContactList, MergeAddsCountsAndKeepsTheLargestOverlap) {
  ContactSummary a, b;
  a.contacts = 2; a.points = 3; a.max_overlap = 0.1; a.normal_force_sum = 1.5; a.evaluations = 4;
  b.contacts = 5; b.points = 5; b.max_overlap = 0.05; b.normal_force_sum = 2.0; b.evaluations = 6;
  a.merge(b);
  EXPECT_EQ(a.contacts, 7);
  EXPECT_EQ(a.points, 8);
  EXPECT_DOUBLE_EQ(a.max_overlap, 0.1);
  EXPECT_DOUBLE_EQ(a.normal_force_sum, 3.5);
  EXPECT_EQ(a.evaluations, 10);
}

TEST(ContactList, CoordinationIsContactsPerMember) {
  EXPECT_DOUBLE_EQ(coordination_number(6, 4), 1.5);
  EXPECT_DOUBLE_EQ(coordination_number(3, 0), 0.0);
}

TEST(ContactList, KindNames) {
  EXPECT_STREQ(contact_kind_name(ContactKind::wire_grain), "wire_grain");
  EXPECT_STREQ(contact_kind_name(ContactKind::grain_wall), "grain_wall");
}
