#include "benchmark_options.h"

#include <common/input_error.h>

#include <unistd.h>

#include <filesystem>
#include <sstream>

namespace FloorBlock::Benchmark
{
  namespace
  {
    template <typename Number>
    std::vector<Number>
    number_list(const std::string &flag, const std::string &text)
    {
      std::vector<Number> values;
      std::istringstream  items(text);
      std::string         item;
      while (std::getline(items, item, ','))
        {
          std::istringstream value_text(item);
          Number             value{};
          if (!(value_text >> value) || !(value > 0))
            throw InputError(flag,
                             text,
                             "a comma-separated list of positive numbers");
          values.push_back(value);
        }
      if (values.empty())
        throw InputError(flag, text, "at least one positive number");
      return values;
    }

    std::vector<std::string>
    law_list(const std::string &text)
    {
      std::vector<std::string> laws;
      std::istringstream       items(text);
      std::string              item;
      while (std::getline(items, item, ','))
        {
          if (item != "compliant" && item != "rigid")
            throw InputError("--laws", text, "compliant, rigid or both");
          laws.push_back(item);
        }
      return laws;
    }
  } // namespace

  BenchmarkOptions
  parse_options(int &argc, char **argv, const std::string &default_scene)
  {
    BenchmarkOptions options;
    options.scene_path = default_scene;
    int kept           = 1;
    for (int i = 1; i < argc; ++i)
      {
        const std::string argument = argv[i];
        const auto        value_of = [&](const std::string &flag) {
          return argument.rfind(flag + "=", 0) == 0 ?
                          argument.substr(flag.size() + 1) :
                          std::string();
        };
        if (!value_of("--scene").empty())
          options.scene_path = value_of("--scene");
        else if (!value_of("--set").empty())
          options.overrides.push_back(value_of("--set"));
        else if (!value_of("--refinements").empty())
          options.refinements =
            number_list<double>("--refinements", value_of("--refinements"));
        else if (!value_of("--laws").empty())
          options.joint_laws = law_list(value_of("--laws"));
        else if (!value_of("--hertz_cells").empty())
          options.hertz_cells_per_half_width =
            number_list<unsigned int>("--hertz_cells",
                                      value_of("--hertz_cells"));
        else if (!value_of("--level_time_limit").empty())
          options.level_time_limit =
            number_list<double>("--level_time_limit",
                                value_of("--level_time_limit"))[0];
        else
          argv[kept++] = argv[i];
      }
    argc = kept;
    options.work_directory =
      (std::filesystem::temp_directory_path() /
       ("floorblock_benchmark_" + std::to_string(getpid())))
        .string();
    return options;
  }

  std::string
  options_help()
  {
    return "FloorBlock benchmark flags (besides Google Benchmark's):\n"
           "  --scene=FILE            scene file (default params/default.prm)\n"
           "  --set=\"Sub/Entry=v\"     override a scene parameter "
           "(repeatable)\n"
           "  --refinements=0.5,1,2   divide Mesh/Corner size and Mesh/Far "
           "size by each\n"
           "  --laws=compliant,rigid  joint laws of the whole contact solve\n"
           "  --hertz_cells=16,32,64  Hertz contact cells per half-width\n"
           "  --level_time_limit=120  skip finer contact solves of a law "
           "after one took longer (s)\n";
  }
} // namespace FloorBlock::Benchmark
