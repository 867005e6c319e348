// See io.hpp. POSIX: read/write/poll on descriptors, sigaction, a self-pipe.
#include "io.hpp"

#include <algorithm>  // std::min
#include <atomic>   // the stop flag
#include <cerrno>   // errno
#include <csignal>  // SIGINT, SIGTERM, sigaction
#include <cstring>  // std::memcpy
#include <ios>      // std::ios_base::failure

#include <fcntl.h>   // open, fcntl
#include <poll.h>    // poll
#include <unistd.h>  // read, write, close, pipe

namespace boxcyl::cli {

namespace {

// Set by the handler; lock-free, so storing it from a signal handler is safe.
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);
// The stop pipe: the handler writes a byte to [1] (non-blocking); readers poll [0]. -1 until installed.
int g_stop_pipe[2] = {-1, -1};

extern "C" void on_stop_signal(int sig) {
    const int saved = errno;
    g_stop_signal.store(sig, std::memory_order_relaxed);
    if (g_stop_pipe[1] >= 0) {
        const char byte = 's';
        [[maybe_unused]] const ssize_t n = ::write(g_stop_pipe[1], &byte, 1);  // full pipe: already woken
    }
    errno = saved;
}

bool set_cloexec_nonblock(int fd, bool nonblock) {
    const int fdflags = ::fcntl(fd, F_GETFD);
    if (fdflags < 0 || ::fcntl(fd, F_SETFD, fdflags | FD_CLOEXEC) < 0) return false;
    if (!nonblock) return true;
    const int flags = ::fcntl(fd, F_GETFL);
    return flags >= 0 && ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) >= 0;
}

// Thrown out of underflow for a read error; the istream catches it and sets badbit.
struct ReadFailed : std::ios_base::failure {
    ReadFailed() : std::ios_base::failure("read error") {}
};

}  // namespace

void install_stop_handlers() {
    if (g_stop_pipe[0] >= 0) return;
    int p[2];
    if (::pipe(p) == 0) {
        if (set_cloexec_nonblock(p[0], true) && set_cloexec_nonblock(p[1], true)) {
            g_stop_pipe[0] = p[0];
            g_stop_pipe[1] = p[1];
        } else {
            ::close(p[0]);
            ::close(p[1]);
        }
    }
    // Without the pipe a signal still sets the flag; a reader blocked in read() then notices it at its
    // next line (the flag is checked before every read).
    for (int sig : {SIGINT, SIGTERM}) {
        struct sigaction old {};
        if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;
        struct sigaction sa {};
        sa.sa_handler = on_stop_signal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESETHAND;  // no SA_RESTART: an interrupted read returns EINTR
        ::sigaction(sig, &sa, nullptr);
    }
}

int stop_signal() { return g_stop_signal.load(std::memory_order_relaxed); }

void set_stop_signal_for_testing(int sig) { g_stop_signal.store(sig, std::memory_order_relaxed); }

FdInBuf::~FdInBuf() {
    if (owned_ && fd_ >= 0) ::close(fd_);
}

FdInBuf::int_type FdInBuf::underflow() {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (interrupted_ || error_ != 0) return traits_type::eof();
    for (;;) {
        if (stop_signal() != 0) {
            interrupted_ = true;
            return traits_type::eof();
        }
        // Wait for input or a stop signal: a read on an idle pipe or terminal would not return for
        // the signal (the handler may run on another thread, and interrupted reads are not all
        // reported as EINTR). Before waiting, the hook.
        pollfd fds[2] = {{fd_, POLLIN, 0}, {g_stop_pipe[0], POLLIN, 0}};
        const nfds_t n = g_stop_pipe[0] >= 0 ? 2 : 1;
        int ready = ::poll(fds, n, 0);
        if (ready == 0) {
            if (before_wait_) before_wait_();
            ready = ::poll(fds, n, -1);
        }
        if (ready < 0 && errno != EINTR) {
            error_ = errno;
            throw ReadFailed();
        }
        if (ready <= 0) continue;  // interrupted: check the flag again
        if (n == 2 && (fds[1].revents & POLLIN) && fds[0].revents == 0) {
            // Only the stop pipe: drained, in case the flag was cleared (tests), then checked again.
            char drain[64];
            while (::read(g_stop_pipe[0], drain, sizeof drain) > 0) {
            }
            continue;
        }
        const ssize_t got = ::read(fd_, buffer_.data(), buffer_.size());
        if (got > 0) {
            setg(buffer_.data(), buffer_.data(), buffer_.data() + got);
            return traits_type::to_int_type(*gptr());
        }
        if (got == 0) return traits_type::eof();
        if (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK) continue;
        error_ = errno;
        throw ReadFailed();
    }
}

bool FdOutBuf::drain() {
    const char* p = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    while (left > 0) {
        const ssize_t n = ::write(fd_, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            if (errno == EAGAIN || errno == EWOULDBLOCK) {  // a non-blocking descriptor: wait for room
                pollfd f{fd_, POLLOUT, 0};
                if (::poll(&f, 1, -1) >= 0 || errno == EINTR) continue;
            }
            error_ = errno;
            return false;
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return true;
}

FdOutBuf::int_type FdOutBuf::overflow(int_type c) {
    if (error_ != 0 || !drain()) return traits_type::eof();
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
    return c;
}

std::streamsize FdOutBuf::xsputn(const char* s, std::streamsize n) {
    std::streamsize done = 0;
    while (done < n) {
        if (error_ != 0) return done;
        const std::streamsize room = epptr() - pptr();
        if (room == 0) {
            if (!drain()) return done;
            continue;
        }
        const std::streamsize k = std::min(room, n - done);
        std::memcpy(pptr(), s + done, static_cast<std::size_t>(k));
        pbump(static_cast<int>(k));
        done += k;
    }
    return done;
}

int FdOutBuf::sync() { return error_ == 0 && drain() ? 0 : -1; }

std::unique_ptr<InputFd> open_input_fd(const std::string& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return nullptr;
    return std::make_unique<InputFd>(fd, true);
}

int stream_error(const std::istream& s) {
    if (const auto* b = dynamic_cast<const FdInBuf*>(s.rdbuf())) return b->error();
    return 0;
}

int stream_error(const std::ostream& s) {
    if (const auto* b = dynamic_cast<const FdOutBuf*>(s.rdbuf())) return b->error();
    return 0;
}

bool stream_interrupted(const std::istream& s) {
    if (const auto* b = dynamic_cast<const FdInBuf*>(s.rdbuf())) return b->interrupted();
    return false;
}

BeforeWait::BeforeWait(std::istream& s, std::function<void()> f) : buf_(dynamic_cast<FdInBuf*>(s.rdbuf())) {
    if (buf_) buf_->set_before_wait(std::move(f));
}

BeforeWait::~BeforeWait() {
    if (buf_) buf_->set_before_wait(nullptr);
}

void guard_standard_descriptors() {
    const int modes[3] = {O_WRONLY, O_RDONLY, O_RDONLY};
    for (int fd = 0; fd < 3; ++fd) {
        if (::fcntl(fd, F_GETFD) >= 0 || errno != EBADF) continue;
        const int r = ::open("/dev/null", modes[fd]);
        if (r >= 0 && r != fd) {
            ::dup2(r, fd);
            ::close(r);
        }
    }
}

}  // namespace boxcyl::cli
