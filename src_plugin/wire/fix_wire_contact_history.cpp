#include "fix_wire_contact_history.h"

#include <cstring>
#include <string>
#include <utility>

#include "atom.h"
#include "error.h"
#include "memory.h"

#include "plugin_args.h"
#include "plugin_comm.h"
#include "core/contact/soft_contact.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixWireContactHistory::FixWireContactHistory(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg),
      count_(NULL),
      new_count_(NULL),
      partner_(NULL),
      new_partner_(NULL),
      value_(NULL),
      new_value_(NULL),
      nmax_(0) {
  wiregrain_lmp::StyleArgs args(error, "fix", "wire/contact/history", id, narg, arg, 3);
  if (!args.done()) args.unknown_keyword(args.next_keyword());
  restart_peratom = 1;
  create_attribute = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(0);
  atom->add_callback(1);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixWireContactHistory::~FixWireContactHistory() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(count_);
  memory->destroy(new_count_);
  memory->destroy(partner_);
  memory->destroy(new_partner_);
  memory->destroy(value_);
  memory->destroy(new_value_);
}

int FixWireContactHistory::setmask() { return 0; }

void FixWireContactHistory::begin_step() {
  for (int i = 0; i < atom->nlocal; i++) new_count_[i] = 0;
}

void FixWireContactHistory::lookup(int i, int partner, wiregrain::TangentialHistory &h) const {
  for (int k = 0; k < count_[i]; k++)
    if (partner_[i][k] == partner) {
      const double *v = &value_[i][k * kValues];
      h.spring = Eigen::Vector3d(v[0], v[1], v[2]);
      h.sliding = v[3] != 0.0;
      return;
    }
  h = wiregrain::TangentialHistory();
}

void FixWireContactHistory::store(int i, int partner, const wiregrain::TangentialHistory &h) {
  int k = new_count_[i];
  if (k == kMaxPartners) {
    const std::string msg = "fix wire/contact/history (id " + std::string(id) + "): bead " +
                            std::to_string(atom->tag[i]) + " has more than " +
                            std::to_string(kMaxPartners) + " contacts (overlaps far too large?)";
    error->one(FLERR, msg.c_str());
  }
  new_partner_[i][k] = partner;
  double *v = &new_value_[i][k * kValues];
  v[0] = h.spring.x();
  v[1] = h.spring.y();
  v[2] = h.spring.z();
  v[3] = h.sliding ? 1.0 : 0.0;
  new_count_[i] = k + 1;
}

// The two lists trade places instead of copying every bead's rows (both are grown
// together, and the one that becomes this step's is emptied by begin_step).
void FixWireContactHistory::end_step() {
  std::swap(count_, new_count_);
  std::swap(partner_, new_partner_);
  std::swap(value_, new_value_);
}

int FixWireContactHistory::stored_count() const {
  int n = 0;
  for (int i = 0; i < atom->nlocal; i++) n += count_[i];
  return n;
}

void FixWireContactHistory::grow_arrays(int nmax) {
  memory->grow(count_, nmax, "wire/contact/history:count");
  memory->grow(new_count_, nmax, "wire/contact/history:new_count");
  memory->grow(partner_, nmax, kMaxPartners, "wire/contact/history:partner");
  memory->grow(new_partner_, nmax, kMaxPartners, "wire/contact/history:new_partner");
  memory->grow(value_, nmax, kMaxPartners * kValues, "wire/contact/history:value");
  memory->grow(new_value_, nmax, kMaxPartners * kValues, "wire/contact/history:new_value");
  for (int i = nmax_; i < nmax; i++) count_[i] = new_count_[i] = 0;
  nmax_ = nmax;
}

void FixWireContactHistory::copy_arrays(int i, int j, int /*delflag*/) {
  count_[j] = count_[i];
  std::memcpy(partner_[j], partner_[i], count_[i] * sizeof(int));
  std::memcpy(value_[j], value_[i], count_[i] * kValues * sizeof(double));
}

void FixWireContactHistory::set_arrays(int i) { count_[i] = 0; }

int FixWireContactHistory::pack(int i, double *buf) const {
  int m = 0;
  buf[m++] = count_[i];
  for (int k = 0; k < count_[i]; k++) {
    buf[m++] = partner_[i][k];
    for (int c = 0; c < kValues; c++) buf[m++] = value_[i][k * kValues + c];
  }
  return m;
}

int FixWireContactHistory::unpack(int i, const double *buf) {
  int m = 0;
  count_[i] = static_cast<int>(buf[m++]);
  for (int k = 0; k < count_[i]; k++) {
    partner_[i][k] = static_cast<int>(buf[m++]);
    for (int c = 0; c < kValues; c++) value_[i][k * kValues + c] = buf[m++];
  }
  return m;
}

int FixWireContactHistory::pack_exchange(int i, double *buf) { return pack(i, buf); }

int FixWireContactHistory::unpack_exchange(int nlocal, double *buf) { return unpack(nlocal, buf); }

int FixWireContactHistory::pack_restart(int i, double *buf) {
  const int m = pack(i, buf + 1);
  buf[0] = m + 1;
  return m + 1;
}

void FixWireContactHistory::unpack_restart(int nlocal, int nth) {
  const double *record = wiregrain_lmp::fix_restart_record(atom, nlocal, nth, -1);
  if (record) unpack(nlocal, record);
  else set_arrays(nlocal);
}

int FixWireContactHistory::size_restart(int nlocal) { return 2 + count_[nlocal] * (1 + kValues); }

int FixWireContactHistory::maxsize_restart() { return 2 + kMaxPartners * (1 + kValues); }

double FixWireContactHistory::memory_usage() {
  return double(nmax_) * (2 * sizeof(int) + 2 * kMaxPartners * (sizeof(int) + kValues * sizeof(double)));
}
