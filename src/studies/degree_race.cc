#include <studies/degree_race.h>

#include <limits>

namespace FloorBlock::Studies
{
  RaceTurn
  next_race_turn(const RacerState &degree_1, const RacerState &degree_2)
  {
    if (degree_1.met || degree_2.met || degree_1.out_of_time ||
        degree_2.out_of_time)
      return RaceTurn::over;
    if (!degree_2.joined)
      {
        if ((!degree_1.checked || degree_1.confirming) && !degree_1.finished)
          return RaceTurn::degree_1;
        return RaceTurn::degree_2;
      }
    if (degree_1.finished && degree_2.finished)
      return RaceTurn::over;
    if (degree_1.finished)
      return RaceTurn::degree_2;
    if (degree_2.finished)
      return RaceTurn::degree_1;
    if (degree_1.confirming)
      return RaceTurn::degree_1;
    if (degree_2.confirming)
      return RaceTurn::degree_2;
    return degree_2.time_spent < degree_1.time_spent ? RaceTurn::degree_2 :
                                                       RaceTurn::degree_1;
  }

  unsigned int
  race_winner(const RacerState &degree_1, const RacerState &degree_2)
  {
    if (degree_1.met)
      return 1;
    if (degree_2.met)
      return 2;
    if (!degree_2.joined)
      return 1;
    const double unbounded = std::numeric_limits<double>::infinity();
    return degree_2.reported_error.value_or(unbounded) <
               degree_1.reported_error.value_or(unbounded) ?
             2 :
             1;
  }
} // namespace FloorBlock::Studies
