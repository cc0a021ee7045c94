#include <output/strength_factor_picture.h>

#include <fmt/format.h>

namespace FloorBlock::Output
{
  std::string
  strength_factor_plot(const Safety::StrengthFactorMap &map,
                       const double                     critical_distance)
  {
    // Millimetres from the corner's surface point, so the axes read as
    // distances at the scale of the critical distance.
    const double to_mm = 1e3;
    std::string  data  = "$f << EOD\n";
    for (unsigned int j = 0; j < map.n_y; ++j)
      {
        for (unsigned int i = 0; i < map.n_x; ++i)
          {
            const auto &factor = map.factors[j * map.n_x + i];
            data += fmt::format(
              "{:.4f} {:.4f} {}\n",
              (map.x_min + i * map.spacing - map.corner.start.x) * to_mm,
              (map.y_min + j * map.spacing - map.corner.start.y) * to_mm,
              factor ? fmt::format("{:.5g}", *factor) : std::string("NaN"));
          }
        data += "\n";
      }
    data += "EOD\n";
    const auto  &path = map.corner;
    const double end_x = path.direction.x * critical_distance * to_mm;
    const double end_y = path.direction.y * critical_distance * to_mm;
    return data +
           fmt::format(
             "set table $c\nunset surface\nset contour base\nset cntrparam "
             "levels discrete 1\nsplot $f using 1:2:3 with lines notitle\n"
             "unset table\nunset contour\nset surface\n"
             "set title \"Hoek-Brown strength factor FS around the {} "
             "corner\\n(FS < 1: the stress exceeds the rock mass's "
             "strength)\"\n"
             "set size ratio -1\nset xlabel 'x from the corner (mm)'\n"
             "set ylabel 'y from the corner (mm)'\nset cbrange [0:2]\n"
             "set cblabel 'FS'\nset palette defined (0 'dark-red', 1 "
             "'yellow', 2 'dark-green')\nset key below\n"
             "set arrow from 0,0 to {:.4f},{:.4f} nohead lc rgb 'white' lw 2 "
             "front\nplot $f using 1:2:3 with image notitle, $c using 1:2 "
             "with lines lc rgb 'black' lw 2 title 'FS = 1', NaN with lines "
             "lc rgb 'white' lw 2 title 'critical distance L along the "
             "path'\n",
             path.label(),
             end_x,
             end_y);
  }
} // namespace FloorBlock::Output
