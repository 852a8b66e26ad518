#include "netsph/app/logging.hpp"

#include <memory>

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace netsph::app {

void log_to_console(bool quiet) {
  auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  console->set_pattern("%^[%l]%$ %v");
  console->set_level(quiet ? spdlog::level::warn : spdlog::level::info);
  auto logger = std::make_shared<spdlog::logger>("netsph", console);
  logger->set_level(spdlog::level::info);
  spdlog::set_default_logger(logger);
}

void log_also_to_file(const std::filesystem::path& file, bool append) {
  auto sink = std::make_shared<spdlog::sinks::basic_file_sink_mt>(file.string(), !append);
  sink->set_pattern("[%Y-%m-%d %H:%M:%S.%e] [%l] %v");
  sink->set_level(spdlog::level::info);
  spdlog::default_logger()->sinks().push_back(sink);
  spdlog::default_logger()->flush_on(spdlog::level::info);
}

}  // namespace netsph::app
