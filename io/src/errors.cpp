#include "antslam/io/errors.hpp"
#include "antslam/io/interrupts.hpp"

#include <cstdio>
#include <new>
#include <system_error>

namespace antslam::io {

namespace {

/// Length of the UTF-8 sequence starting at text[i] (1 to 4), or 0 if it is not one.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  if (lead < 0x80) return 1;
  if (lead >= 0xC2 && lead <= 0xDF)
    length = 2;
  else if (lead >= 0xE0 && lead <= 0xEF)
    length = 3;
  else if (lead >= 0xF0 && lead <= 0xF4)
    length = 4;
  else
    return 0;
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  return length;
}

std::string hex_escape(unsigned char c) {
  char buffer[5];
  std::snprintf(buffer, sizeof buffer, "\\x%02X", c);
  return buffer;
}

std::string filesystem_message(const std::filesystem::filesystem_error& e) {
  std::string message = e.path1().empty() ? std::string("file system") : e.path1().string();
  message += ": " + e.code().message();
  if (!e.path2().empty()) message += " (" + e.path2().string() + ")";
  return message;
}

}  // namespace

std::string one_line(std::string_view text) {
  std::string out;
  bool pending_space = false;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n' || c == '\r' || c == '\t' || c == ' ') {
      pending_space = !out.empty();
      ++i;
      continue;
    }
    if (pending_space) out += ' ';
    pending_space = false;
    const std::size_t length = utf8_length(text, i);
    if (length == 0 || c < 0x20 || c == 0x7F) {
      out += hex_escape(c);
      ++i;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

Failure failure_of(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const Interrupted& e) {
    return {one_line(e.what()), ExitStatus::runtime, e.signal()};
  } catch (const UsageError& e) {
    return {one_line(e.what()), ExitStatus::usage};
  } catch (const InputError& e) {
    return {one_line(e.what()), ExitStatus::input};
  } catch (const OutputError& e) {
    return {one_line(e.what()), ExitStatus::runtime};
  } catch (const std::bad_alloc&) {
    return {"out of memory", ExitStatus::runtime};
  } catch (const std::filesystem::filesystem_error& e) {
    return {one_line(filesystem_message(e)), ExitStatus::runtime};
  } catch (const std::system_error& e) {
    return {one_line(e.what()), ExitStatus::runtime};
  } catch (const std::invalid_argument& e) {
    return {one_line(e.what()), ExitStatus::usage};
  } catch (const std::runtime_error& e) {
    return {one_line(e.what()), ExitStatus::input};
  } catch (const std::exception& e) {
    return {"internal error: " + one_line(e.what()), ExitStatus::runtime};
  } catch (...) {
    return {"internal error: unknown exception", ExitStatus::runtime};
  }
}

namespace detail {

void rethrow_in_context(const std::vector<std::filesystem::path>& files) {
  const auto in_context = [&](const std::exception& e) {
    const std::string message = e.what();
    for (const std::filesystem::path& file : files)
      if (!file.empty() && message.find(file.string()) != std::string::npos)
        return InputError(message);
    return InputError(files.front().string() + ": " + message);
  };
  try {
    throw;
  } catch (const UsageError&) {
    throw;
  } catch (const OutputError&) {
    throw;
  } catch (const std::filesystem::filesystem_error&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw in_context(e);
  } catch (const std::logic_error&) {
    throw;  // an internal error, not the input's
  } catch (const std::system_error&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw in_context(e);
  }
}

}  // namespace detail

}  // namespace antslam::io
