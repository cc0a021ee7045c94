#include <app/command_options.h>

#include <iostream>

namespace FloorBlock::App
{
  int
  print_parameters_command(const CommandOptions &)
  {
    std::cout << Parameters::describe_all_parameters();
    return 0;
  }
} // namespace FloorBlock::App
