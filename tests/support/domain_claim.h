// Claims a DDS domain for one test while it runs, so two tests that share a domain fail at once
// with a clear message instead of answering each other's clients now and then.
#pragma once

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

namespace pool::test {

/// Holds an exclusive lock on /tmp/pool-test-domain-<netns>-<port base>-<domain>.lock (the
/// network namespace and port base are part of the name: tests in another namespace or on
/// another port base do not meet). claimed() is false when another test holds the domain.
class DomainClaim {
 public:
  explicit DomainClaim(std::uint32_t domain) : domain_(domain) {
    struct stat ns {};
    const auto netns = ::stat("/proc/self/ns/net", &ns) == 0 ? ns.st_ino : 0;
    const char* base = std::getenv("POOL_DDS_PORT_BASE");
    path_ = "/tmp/pool-test-domain-" + std::to_string(netns) + "-" + (base ? base : "7400") + "-" +
            std::to_string(domain) + ".lock";
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    claimed_ = fd_ >= 0 && ::flock(fd_, LOCK_EX | LOCK_NB) == 0;
  }
  ~DomainClaim() {
    if (fd_ >= 0) ::close(fd_);  // releases the lock
  }
  DomainClaim(const DomainClaim&) = delete;
  DomainClaim& operator=(const DomainClaim&) = delete;

  bool claimed() const { return claimed_; }
  /// The failure message for a test's assertion when claimed() is false.
  std::string refusal() const {
    return "domain " + std::to_string(domain_) + " is in use by another test (" + path_ +
           "): give each test a domain of its own";
  }
  std::uint32_t domain() const { return domain_; }
  const std::string& path() const { return path_; }

 private:
  std::uint32_t domain_;
  std::string path_;
  int fd_ = -1;
  bool claimed_ = false;
};

/// Ends the test when `claim` did not get its domain: throws, which GoogleTest reports as the
/// test's failure with the refusal and stops the test there (an assertion inside a fixture's
/// helper would return from the helper only, and the test would run on without its fixture).
inline void requireClaim(const DomainClaim& claim) {
  if (!claim.claimed()) throw std::runtime_error(claim.refusal());
}

/// Makes `held` claim `domain`: kept when it already does (a restart within one test), else
/// released and claimed afresh. The fixtures then requireClaim.
inline void claimDomain(std::unique_ptr<DomainClaim>& held, std::uint32_t domain) {
  if (held && held->domain() == domain) return;
  held.reset();
  held = std::make_unique<DomainClaim>(domain);
}

}  // namespace pool::test
