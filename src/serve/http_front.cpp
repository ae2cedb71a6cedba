#include "serve/http_front.hpp"

#include <algorithm>
#include <cerrno>
#include <utility>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace pita::serve {

namespace {

using Clock = std::chrono::steady_clock;

// The address and port of a socket's end (getsockname or getpeername).
void address_of(int fd, bool peer, std::string& ip, int& port) {
  sockaddr_storage address{};
  socklen_t size = sizeof(address);
  const int status = peer ? ::getpeername(fd, reinterpret_cast<sockaddr*>(&address), &size)
                          : ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size);
  ip.clear();
  port = 0;
  if (status != 0) return;
  char text[INET6_ADDRSTRLEN] = {};
  if (address.ss_family == AF_INET) {
    const auto* v4 = reinterpret_cast<const sockaddr_in*>(&address);
    ::inet_ntop(AF_INET, &v4->sin_addr, text, sizeof(text));
    port = ntohs(v4->sin_port);
  } else if (address.ss_family == AF_INET6) {
    const auto* v6 = reinterpret_cast<const sockaddr_in6*>(&address);
    ::inet_ntop(AF_INET6, &v6->sin6_addr, text, sizeof(text));
    port = ntohs(v6->sin6_port);
  }
  ip = text;
}

// Waits until `fd` is ready for `events`, at most `wait`; true when it is.
bool ready(int fd, short events, std::chrono::milliseconds wait) {
  pollfd one{fd, events, 0};
  int status = 0;
  do {
    status = ::poll(&one, 1, static_cast<int>(wait.count()));
  } while (status < 0 && errno == EINTR);
  return status > 0;
}

// Writes all of `data`, each part within 5 s; false when the peer is gone or stuck.
bool send_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    if (!ready(fd, POLLOUT, std::chrono::seconds(5))) return false;
    const ssize_t sent = ::send(fd, data, size, MSG_NOSIGNAL);
    if (sent < 0 && errno == EINTR) continue;
    if (sent <= 0) return false;
    data += sent;
    size -= static_cast<std::size_t>(sent);
  }
  return true;
}

// A request already received whole, read from memory: what cpp-httplib reads.
class ReceivedRequest : public httplib::Stream {
 public:
  explicit ReceivedRequest(std::string request) : request_(std::move(request)) {}
  bool is_readable() const override { return read_ < request_.size(); }
  ssize_t read(char* ptr, std::size_t size) override {
    const std::size_t n = std::min(size, request_.size() - read_);
    std::copy_n(request_.data() + read_, n, ptr);
    read_ += n;
    return static_cast<ssize_t>(n);
  }

 private:
  std::string request_;
  std::size_t read_ = 0;
};

// The request received whole, then the socket for the answer.
class ReceivedStream : public ReceivedRequest {
 public:
  ReceivedStream(std::string request, int fd) : ReceivedRequest(std::move(request)), fd_(fd) {}
  bool is_writable() const override { return ready(fd_, POLLOUT, std::chrono::seconds(5)); }
  ssize_t write(const char* ptr, std::size_t size) override {
    return send_all(fd_, ptr, size) ? static_cast<ssize_t>(size) : -1;
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override { address_of(fd_, true, ip, port); }
  void get_local_ip_and_port(std::string& ip, int& port) const override { address_of(fd_, false, ip, port); }
  socket_t socket() const override { return fd_; }

 private:
  int fd_;
};

// A request given as bytes, and its answer gathered (at most 64 MiB).
class MemoryStream : public ReceivedRequest {
 public:
  explicit MemoryStream(std::string_view request) : ReceivedRequest(std::string(request)) {}
  bool is_writable() const override { return answer_.size() < (64U << 20); }
  ssize_t write(const char* ptr, std::size_t size) override {
    answer_.append(ptr, size);
    return static_cast<ssize_t>(size);
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    ip = "127.0.0.1";
    port = 0;
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    ip = "127.0.0.1";
    port = 0;
  }
  socket_t socket() const override { return INVALID_SOCKET; }
  std::string take() { return std::move(answer_); }

 private:
  std::string answer_;
};

// Closes a connection after its answer: what the client still sends is read
// and dropped for a moment (at most 256 KiB, 500 ms), so that the kernel
// does not reset the connection before the client has read the answer.
void close_gently(int fd) {
  ::shutdown(fd, SHUT_WR);
  const Clock::time_point end = Clock::now() + std::chrono::milliseconds(500);
  char sink[4096];
  std::size_t dropped = 0;
  while (dropped < (256U << 10) && Clock::now() < end && ready(fd, POLLIN, std::chrono::milliseconds(100))) {
    const ssize_t got = ::recv(fd, sink, sizeof(sink), MSG_DONTWAIT);
    if (got <= 0) break;
    dropped += static_cast<std::size_t>(got);
  }
  ::close(fd);
}

}  // namespace

HttpFront::HttpFront(HttpLimits limits, std::vector<std::string> hosts) : limits_(limits), hosts_(std::move(hosts)) {}

std::string HttpFront::receive(socket_t sock) {
  const Place place(receiving_);
  const Clock::time_point deadline = Clock::now() + kRequestSeconds;
  std::string received;
  char buffer[16384];
  while (true) {
    const RequestVerdict verdict = check_request(received, limits_, hosts_);
    if (verdict.what == RequestVerdict::What::complete) return received.substr(0, verdict.size);
    if (verdict.what == RequestVerdict::What::refused) {
      const std::string answer = refusal(verdict.status, verdict.reason);
      send_all(sock, answer.data(), answer.size());
      return "";
    }
    // Waits in slices, to notice a stop or a newer request.
    while (!ready(sock, POLLIN, std::chrono::milliseconds(100))) {
      if (stopping_) return "";
      if (place.told_to_leave() || Clock::now() > deadline) {
        const std::string answer =
            refusal(408, place.told_to_leave() ? "too many requests were being received at once: the oldest was closed"
                                               : "the request did not arrive whole within 10 s");
        send_all(sock, answer.data(), answer.size());
        return "";
      }
    }
    const ssize_t got = ::recv(sock, buffer, sizeof(buffer), MSG_DONTWAIT);
    if (got < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (got <= 0) return "";  // the client left
    received.append(buffer, static_cast<std::size_t>(got));
  }
}

bool HttpFront::process_and_close_socket(socket_t sock) {
  std::string request = receive(sock);
  if (!request.empty()) {
    ReceivedStream stream(std::move(request), sock);
    bool closed = false;
    process_request(stream, true, closed, nullptr);
  }
  close_gently(sock);
  return true;
}

std::string HttpFront::answer(std::string_view request) {
  const RequestVerdict verdict = check_request(request, limits_, hosts_);
  if (verdict.what == RequestVerdict::What::refused) return refusal(verdict.status, verdict.reason);
  if (verdict.what == RequestVerdict::What::incomplete) return refusal(400, "the request ended before it was whole");
  MemoryStream stream(request.substr(0, verdict.size));
  bool closed = false;
  process_request(stream, true, closed, nullptr);
  return stream.take();
}

}  // namespace pita::serve
