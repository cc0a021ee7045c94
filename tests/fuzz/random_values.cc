#include "random_values.h"

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <vector>

namespace FloorBlock::Fuzz
{
  std::size_t
  random_index(RandomEngine &engine, const std::size_t count)
  {
    return std::uniform_int_distribution<std::size_t>(0, count - 1)(engine);
  }

  bool
  random_chance(RandomEngine &engine, const double probability)
  {
    return std::bernoulli_distribution(probability)(engine);
  }

  std::string
  random_bytes(RandomEngine &engine, const std::size_t length)
  {
    std::string bytes;
    for (std::size_t i = 0; i < length; ++i)
      bytes += static_cast<char>(1 + random_index(engine, 255));
    return bytes;
  }

  namespace
  {
    // Longest generated strings: long enough to cross small-buffer and
    // line-buffer sizes, short enough to keep thousands of inputs fast.
    constexpr std::size_t longest_string = 5000;

    /// A number spread over 640 decades (both signs), in a random notation.
    std::string
    wide_number(RandomEngine &engine)
    {
      const double exponent =
        std::uniform_real_distribution<double>(-320., 320.)(engine);
      const double magnitude = std::pow(10., exponent);
      const double value = random_chance(engine, 0.3) ? -magnitude : magnitude;
      std::ostringstream text;
      switch (random_index(engine, 3))
        {
          case 0:
            text.precision(17);
            text << value;
            break;
          case 1:
            text << std::scientific << value;
            break;
          default:
            text << std::hexfloat << value;
        }
      return text.str();
    }

    /// A number of ordinary size (-1000..1000), the region the patterns allow.
    std::string
    plausible_number(RandomEngine &engine)
    {
      const double value =
        std::uniform_real_distribution<double>(-1000., 1000.)(engine);
      std::ostringstream text;
      text.precision(1 + random_index(engine, 17));
      text << (random_chance(engine, 0.5) ? value : std::round(value / 10.));
      return text.str();
    }

    std::string
    long_string(RandomEngine &engine)
    {
      const std::size_t length = 1 + random_index(engine, longest_string);
      const std::array<std::string, 4> units = {{"9", "1.0", "a", " "}};
      std::string                      text;
      const std::string &unit = units[random_index(engine, units.size())];
      while (text.size() < length)
        text += unit;
      return text;
    }

    std::string
    number_list(RandomEngine &engine)
    {
      std::string       list;
      const std::size_t n_entries = random_index(engine, 120);
      for (std::size_t i = 0; i < n_entries; ++i)
        list +=
          (i > 0 ? "," : "") +
          std::to_string(static_cast<long>(random_index(engine, 205)) - 2);
      return list;
    }

    const std::vector<std::string> &
    special_spellings()
    {
      static const std::vector<std::string> spellings = {"",
                                                         " ",
                                                         "\t",
                                                         "nan",
                                                         "NaN",
                                                         "-nan",
                                                         "inf",
                                                         "-inf",
                                                         "Infinity",
                                                         "1e308",
                                                         "1.8e308",
                                                         "-1e308",
                                                         "1e-308",
                                                         "4.9e-324",
                                                         "1e-400",
                                                         "0",
                                                         "-0",
                                                         "+0",
                                                         "0.0",
                                                         "1",
                                                         "-1",
                                                         "2",
                                                         "99",
                                                         "100",
                                                         "-2147483648",
                                                         "2147483647",
                                                         "4294967295",
                                                         "4294967296",
                                                         "18446744073709551616",
                                                         "0x10",
                                                         "0x1p-1074",
                                                         "1e",
                                                         "e5",
                                                         "--1",
                                                         "+-1",
                                                         "1.0.0",
                                                         "1,5",
                                                         "1 5",
                                                         "3m",
                                                         "30 deg",
                                                         "1e9Pa",
                                                         "true",
                                                         "false",
                                                         "yes",
                                                         "no",
                                                         "planar",
                                                         "parabolic",
                                                         "compliant",
                                                         "rigid",
                                                         "planar|parabolic",
                                                         "4,5,6",
                                                         "4,4",
                                                         ",",
                                                         ",,",
                                                         "1,",
                                                         ",1",
                                                         "0,1",
                                                         "99,98,97",
                                                         "½",
                                                         "１２",
                                                         "٣",
                                                         "3\xC2\xA0"
                                                         "5",
                                                         "\xE2\x80\x8B"
                                                         "1",
                                                         "\xFF\xFE",
                                                         "\\",
                                                         "#",
                                                         "# comment",
                                                         "=",
                                                         "==",
                                                         "set",
                                                         "end",
                                                         "subsection",
                                                         "include",
                                                         "'quoted'",
                                                         "\"1\"",
                                                         "{}",
                                                         "[]",
                                                         "<x/>",
                                                         "%s%n",
                                                         "${HOME}"};
      return spellings;
    }
  } // namespace

  std::string
  random_value(RandomEngine &engine)
  {
    const std::array<std::function<std::string()>, 7> makers = {
      {[&] { return wide_number(engine); },
       [&] { return plausible_number(engine); },
       [&] { return plausible_number(engine); },
       [&] { return long_string(engine); },
       [&] { return number_list(engine); },
       [&] { return random_bytes(engine, 1 + random_index(engine, 40)); },
       [&] {
         const auto &spellings = special_spellings();
         return spellings[random_index(engine, spellings.size())];
       }}};
    return makers[random_index(engine, makers.size())]();
  }
} // namespace FloorBlock::Fuzz

namespace FloorBlock::Fuzz
{
  double
  random_double(RandomEngine &engine)
  {
    using limits                          = std::numeric_limits<double>;
    const std::array<double, 10> specials = {{limits::quiet_NaN(),
                                              limits::infinity(),
                                              -limits::infinity(),
                                              0.,
                                              -0.,
                                              limits::denorm_min(),
                                              limits::min(),
                                              limits::max(),
                                              -limits::max(),
                                              limits::epsilon()}};
    switch (random_index(engine, 6))
      {
        case 0:
          return specials[random_index(engine, specials.size())];
          case 1: {
            // Any magnitude, either sign.
            const double exponent =
              std::uniform_real_distribution<double>(-320., 308.)(engine);
            return (random_chance(engine, 0.5) ? -1. : 1.) *
                   std::pow(10., exponent);
          }
        case 2:
          // Angles, including around +-pi/2 and beyond.
          return std::uniform_real_distribution<double>(-2., 2.)(engine);
        default:
          // Lengths and forces of real scenes, mostly non-negative.
          return std::uniform_real_distribution<double>(-0.1, 1.)(engine) *
                 std::pow(10.,
                          std::uniform_real_distribution<double>(-3.,
                                                                 7.)(engine));
      }
  }
} // namespace FloorBlock::Fuzz
