#include "stages/tpg_stitch.h"

#include <array>

namespace tessref::tpg {
namespace {

// Half rows hold at most 32 stitching slots (level 64). Slot s becomes active once a half row has
// more than kSlotRank[s] points. Slot 0 always comes first; the others follow a ruler function
// of s - 1 (largest power of two dividing it first, ascending within a power, and s = 1 last), so
// that growing a level inserts points evenly across the half row.
constexpr int kSlots = 33;
constexpr std::array<int, kSlots> make_slot_rank() {
  std::array<int, kSlots> rank{};
  int next = 1;
  for (int power = 4; power >= 0; --power) {
    for (int s = 2; s < kSlots; ++s) {
      const int m = s - 1;
      int tz = 0;
      while (((m >> tz) & 1) == 0) ++tz;
      if (tz == power) rank[s] = next++;
    }
  }
  rank[1] = next;  // 32
  return rank;
}
constexpr std::array<int, kSlots> kSlotRank = make_slot_rank();
static_assert(kSlotRank[17] == 1 && kSlotRank[9] == 2 && kSlotRank[25] == 3 && kSlotRank[3] == 8 &&
              kSlotRank[2] == 16 && kSlotRank[32] == 31 && kSlotRank[1] == 32);

}  // namespace

void stitch_regular(bool trapezoid, Diagonals diagonals, int inside_points, const Row& in,
                    const Row& out, const TriangleSink& emit) {
  int i = 0, o = 0;
  auto quad_outward = [&] {  // diagonal from the inside point to the next outside point
    emit(in(i), out(o), out(o + 1));
    emit(in(i), out(o + 1), in(i + 1));
    ++i, ++o;
  };
  auto quad_inward = [&] {  // diagonal from the outside point to the next inside point
    emit(out(o), in(i + 1), in(i));
    emit(out(o), out(o + 1), in(i + 1));
    ++i, ++o;
  };
  if (trapezoid) emit(out(o), out(o + 1), in(i)), ++o;
  int p = 0;
  switch (diagonals) {
    case Diagonals::InsideToOutside:
      for (; p < inside_points - 1; ++p) quad_outward();
      break;
    case Diagonals::InsideToOutsideExceptMiddle: {
      auto quad_split = [&] {
        emit(out(o), out(o + 1), in(i));
        emit(in(i), out(o + 1), in(i + 1));
        ++i, ++o;
      };
      for (; p < inside_points / 2 - 1; ++p) quad_split();
      quad_inward();
      for (p += 2; p < inside_points; ++p) quad_split();
      break;
    }
    case Diagonals::Mirrored:
      for (; p < inside_points / 2; ++p) quad_inward();
      for (; p < inside_points - 1; ++p) quad_outward();
      break;
  }
  if (trapezoid) emit(out(o), out(o + 1), in(i));
}

void stitch_transition(const Row& in, int inside_half_points, Parity inside_parity,
                       const Row& out, int outside_half_points, Parity outside_parity,
                       const TriangleSink& emit) {
  // Odd rows have a centre segment instead of a midpoint: one slot fewer on each half.
  const int in_slots = inside_half_points - (inside_parity == Parity::Odd ? 1 : 0);
  const int out_slots = outside_half_points - (outside_parity == Parity::Odd ? 1 : 0);
  int i = 0, o = 0;
  auto advance_inside = [&] { emit(in(i), out(o), in(i + 1)), ++i; };
  auto advance_outside = [&] { emit(out(o), out(o + 1), in(i)), ++o; };

  // First half, slots in increasing order.
  for (int s = 0; s < kSlots; ++s) {
    if (s > 0 && kSlotRank[s] < in_slots) advance_inside();
    if (kSlotRank[s] < out_slots) advance_outside();
  }
  // The middle: a quad where both rows are odd, one triangle where parities differ.
  if (inside_parity != outside_parity || inside_parity == Parity::Odd) {
    if (inside_parity == outside_parity) {
      emit(in(i), out(o), in(i + 1));
      emit(in(i + 1), out(o), out(o + 1));
      ++i, ++o;
    } else if (inside_parity == Parity::Even) {
      emit(in(i), out(o), out(o + 1)), ++o;
    } else {
      emit(in(i), out(o), in(i + 1)), ++i;
    }
  }
  // Second half, mirrored: slots in decreasing order, outside before inside.
  for (int s = kSlots - 1; s >= 0; --s) {
    if (kSlotRank[s] < out_slots) advance_outside();
    if (s > 0 && kSlotRank[s] < in_slots) advance_inside();
  }
}

}  // namespace tessref::tpg
