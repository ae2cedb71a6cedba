#include "serve/http_request.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace pita::serve {

namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::string_view trim(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return text;
}

std::string kib(std::size_t bytes) {
  return bytes % 1024 == 0 ? fmt::format("{} KiB", bytes / 1024) : fmt::format("{} bytes", bytes);
}

RequestVerdict refuse(int status, std::string reason) {
  return {RequestVerdict::What::refused, 0, status, std::move(reason)};
}

// The host name of a Host header's value: without its port, in lower case;
// an IPv6 address keeps its brackets. Empty when the value is not a host.
std::string host_name(std::string_view value) {
  value = trim(value);
  if (!value.empty() && value.front() == '[') {
    const std::size_t close = value.find(']');
    if (close == std::string_view::npos) return "";
    const std::string_view rest = value.substr(close + 1);
    if (!rest.empty() && (rest.front() != ':' || rest.find_first_not_of("0123456789", 1) != std::string_view::npos)) {
      return "";
    }
    return lower(value.substr(0, close + 1));
  }
  const std::size_t colon = value.rfind(':');
  if (colon != std::string_view::npos) {
    if (value.find_first_not_of("0123456789", colon + 1) != std::string_view::npos) return "";
    value = value.substr(0, colon);
  }
  if (value.find_first_of(" \t/@?#") != std::string_view::npos) return "";
  return lower(value);
}

// What the head's lines say about the body and the host, once all of it is there.
struct Head {
  std::optional<std::size_t> content_length;
  bool transfer_encoding = false;
  int hosts = 0;
  std::string host;
};

// Reads one header line into `head`; a refusal when it is malformed.
std::optional<RequestVerdict> read_header(std::string_view line, const HttpLimits& limits, Head& head) {
  if (line.front() == ' ' || line.front() == '\t')
    return refuse(400, "a header line continues the one before (obsolete line folding)");
  const std::size_t colon = line.find(':');
  if (colon == 0 || colon == std::string_view::npos ||
      line.substr(0, colon).find_first_of(" \t") != std::string_view::npos) {
    return refuse(400, "a header line is not \"Name: value\"");
  }
  const std::string name = lower(line.substr(0, colon));
  const std::string_view value = trim(line.substr(colon + 1));
  if (name == "content-length") {
    if (value.empty() || value.size() > 18 || value.find_first_not_of("0123456789") != std::string_view::npos) {
      return refuse(400, "Content-Length is not a number of bytes");
    }
    const std::size_t length = std::stoull(std::string(value));
    if (head.content_length && *head.content_length != length) return refuse(400, "two Content-Length headers differ");
    if (length > limits.body_bytes) {
      return refuse(413, fmt::format("the body is {} bytes, beyond the limit of {}", length, kib(limits.body_bytes)));
    }
    head.content_length = length;
  } else if (name == "transfer-encoding") {
    head.transfer_encoding = true;
  } else if (name == "host") {
    ++head.hosts;
    head.host = std::string(value);
  }
  return std::nullopt;
}

// The request line: METHOD TARGET HTTP/1.x.
bool is_request_line(std::string_view line) {
  const std::size_t first = line.find(' ');
  const std::size_t last = line.rfind(' ');
  if (first == 0 || first == std::string_view::npos || first == last) return false;
  const std::string_view version = line.substr(last + 1);
  return version == "HTTP/1.1" || version == "HTTP/1.0";
}

std::optional<RequestVerdict> check_host(const Head& head, const std::vector<std::string>& hosts) {
  if (head.hosts != 1)
    return refuse(400, head.hosts == 0 ? "the request has no Host header" : "the request has two Host headers");
  if (hosts.empty()) return std::nullopt;
  const std::string name = host_name(head.host);
  if (std::find(hosts.begin(), hosts.end(), name) != hosts.end()) return std::nullopt;
  return refuse(403, fmt::format("the Host header names \"{}\", not an address of this server (a page of another "
                                 "site may be trying DNS rebinding): open the address pita serve printed",
                                 head.host));
}

}  // namespace

std::vector<std::string> allowed_hosts(const std::string& served_host) {
  const std::string served = lower(served_host);
  if (served.empty() || served == "0.0.0.0" || served == "::" || served == "[::]") return {};
  const std::string bracketed =
      served.find(':') != std::string::npos && served.front() != '[' ? "[" + served + "]" : served;
  if (served == "localhost" || served == "::1" || served.rfind("127.", 0) == 0) {
    std::vector<std::string> loopback{"localhost", "127.0.0.1", "[::1]"};
    if (std::find(loopback.begin(), loopback.end(), bracketed) == loopback.end()) loopback.push_back(bracketed);
    return loopback;
  }
  return {bracketed};
}

RequestVerdict check_request(std::string_view received, const HttpLimits& limits,
                             const std::vector<std::string>& hosts) {
  Head head;
  std::size_t start = 0;
  std::size_t lines = 0;
  while (true) {
    const std::size_t end = received.find('\n', start);
    const std::size_t length = (end == std::string_view::npos ? received.size() : end) - start;
    if (lines == 0 && length > limits.request_line + 1) {
      return refuse(414, fmt::format("the request line is longer than {}", kib(limits.request_line)));
    }
    if ((end == std::string_view::npos ? received.size() : end + 1) > limits.header_bytes) {
      return refuse(431, fmt::format("the request's header is larger than {}", kib(limits.header_bytes)));
    }
    if (end == std::string_view::npos) return {};
    std::string_view line = received.substr(start, length);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    start = end + 1;
    if (lines++ == 0) {
      if (!is_request_line(line)) return refuse(400, "the first line is not an HTTP/1 request line");
      continue;
    }
    if (line.empty()) break;
    if (lines - 1 > limits.header_count) {
      return refuse(431, fmt::format("the request has more than {} header lines", limits.header_count));
    }
    if (auto refused = read_header(line, limits, head)) return *refused;
  }
  if (head.transfer_encoding) {
    return refuse(413, fmt::format("a body sent in chunks (Transfer-Encoding) is refused: send it with a "
                                   "Content-Length of at most {}",
                                   kib(limits.body_bytes)));
  }
  if (auto refused = check_host(head, hosts)) return *refused;
  const std::size_t size = start + head.content_length.value_or(0);
  if (received.size() < size) return {};
  return {RequestVerdict::What::complete, size, 0, ""};
}

std::string refusal(int status, const std::string& reason) {
  const char* phrase = status == 400   ? "Bad Request"
                       : status == 403 ? "Forbidden"
                       : status == 408 ? "Request Timeout"
                       : status == 413 ? "Content Too Large"
                       : status == 414 ? "URI Too Long"
                       : status == 431 ? "Request Header Fields Too Large"
                       : status == 503 ? "Service Unavailable"
                                       : "Error";
  const std::string body =
      nlohmann::json{{"error", reason}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return fmt::format(
      "HTTP/1.1 {} {}\r\nContent-Type: application/json\r\nContent-Length: {}\r\nCache-Control: no-store\r\n"
      "Connection: close\r\n\r\n{}",
      status, phrase, body.size(), body);
}

}  // namespace pita::serve
