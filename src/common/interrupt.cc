#include <common/interrupt.h>
#include <common/wall_clock.h>

#include <csignal>

namespace FloorBlock
{
  namespace
  {
    volatile std::sig_atomic_t interrupt_flag = 0;

    extern "C" void
    record_interrupt(int)
    {
      interrupt_flag = 1;
    }
  } // namespace

  void
  install_interrupt_handlers()
  {
    std::signal(SIGINT, record_interrupt);
    std::signal(SIGTERM, record_interrupt);
  }

  bool
  interrupt_requested()
  {
    return interrupt_flag != 0;
  }

  void
  stop_if_interrupted()
  {
    if (interrupt_requested())
      throw Interrupted();
    if (solve_deadline_passed())
      throw DeadlineReached();
  }
} // namespace FloorBlock
