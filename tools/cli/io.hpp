// The tool's own ends of its files: input and output streams over file descriptors, which say why a
// read or a write failed (errno), and the stop signals (SIGINT, SIGTERM) that end a run cleanly.
//
// A stop signal only sets a flag and wakes the reader (through a pipe written by the handler: both
// async-signal-safe); the reader then stops reading, every line read in full is answered and written
// in input order, and the tool exits with exit_signal_base + the signal (app.hpp). A line cut short by
// the stop is not answered. The handler is installed once, resetting itself (SA_RESETHAND): a second
// signal ends the process at once, the default way. A signal ignored when the tool starts (nohup, a
// background job) stays ignored.
#pragma once

#include <array>      // the buffers
#include <cstddef>    // std::size_t
#include <functional> // FdInBuf's hook
#include <istream>    // InputFd
#include <memory>     // open_input_fd
#include <ostream>    // OutputFd
#include <streambuf>  // the buffers
#include <string>     // file names

namespace boxcyl::cli {

// Installs the SIGINT and SIGTERM handlers (idempotent). Without them stop_signal() stays 0.
void install_stop_handlers();

// The stop signal received (SIGINT or SIGTERM), or 0. Readers check it between lines.
int stop_signal();

// For tests: as if `sig` had arrived (0: clear it).
void set_stop_signal_for_testing(int sig);

// Reads a file descriptor. A read error makes the stream bad (the istream catches the exception
// underflow throws) with its errno kept in error(); a stop signal ends the input (eof) with
// interrupted() set. Before a read that could block it waits on the descriptor and the stop pipe
// together, so that a signal wakes it.
class FdInBuf : public std::streambuf {
public:
    explicit FdInBuf(int fd, bool owned = false) : fd_(fd), owned_(owned) {}
    FdInBuf(const FdInBuf&) = delete;
    FdInBuf& operator=(const FdInBuf&) = delete;
    ~FdInBuf() override;

    int error() const { return error_; }  // errno of the failed read; 0 if none failed
    bool interrupted() const { return interrupted_; }

    // Called (if set) before a read that has to wait for input, e.g. with part of a line read: the
    // tool hands over the answers it has then, so that a caller waiting for them before writing more
    // is not kept waiting. It must not throw.
    void set_before_wait(std::function<void()> f) { before_wait_ = std::move(f); }

protected:
    int_type underflow() override;

private:
    std::function<void()> before_wait_;
    int fd_;
    bool owned_;
    int error_ = 0;
    bool interrupted_ = false;
    std::array<char, std::size_t{64} * 1024> buffer_;
};

// Writes a file descriptor (retrying short and interrupted writes). A write error makes the stream
// bad with its errno kept in error().
class FdOutBuf : public std::streambuf {
public:
    explicit FdOutBuf(int fd) : fd_(fd) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
    FdOutBuf(const FdOutBuf&) = delete;
    FdOutBuf& operator=(const FdOutBuf&) = delete;
    ~FdOutBuf() override { sync(); }

    int error() const { return error_; }  // errno of the failed write; 0 if none failed

protected:
    int_type overflow(int_type c) override;
    int sync() override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;

private:
    bool drain();  // writes the buffer out; false on a write error
    int fd_;
    int error_ = 0;
    std::array<char, std::size_t{64} * 1024> buffer_;
};

class InputFd : public std::istream {
public:
    explicit InputFd(int fd, bool owned = false) : std::istream(nullptr), buf_(fd, owned) { rdbuf(&buf_); }
    const FdInBuf& buffer() const { return buf_; }

private:
    FdInBuf buf_;
};

class OutputFd : public std::ostream {
public:
    explicit OutputFd(int fd) : std::ostream(nullptr), buf_(fd) { rdbuf(&buf_); }
    const FdOutBuf& buffer() const { return buf_; }

private:
    FdOutBuf buf_;
};

// Opens `file` for reading; nullptr with errno set when it cannot be opened.
std::unique_ptr<InputFd> open_input_fd(const std::string& file);

// errno of the failed read or write of a stream over FdInBuf/FdOutBuf, else 0 (other streams).
int stream_error(const std::istream& s);
int stream_error(const std::ostream& s);

// Whether input from `s` ended because of a stop signal.
bool stream_interrupted(const std::istream& s);

// Sets FdInBuf::set_before_wait on `s` for the lifetime of this object, when `s` reads through an
// FdInBuf (otherwise nothing: other streams do not wait).
class BeforeWait {
public:
    BeforeWait(std::istream& s, std::function<void()> f);
    ~BeforeWait();
    BeforeWait(const BeforeWait&) = delete;
    BeforeWait& operator=(const BeforeWait&) = delete;

private:
    FdInBuf* buf_;
};

// Makes sure descriptors 0, 1 and 2 are open, so that no file the tool opens takes their place: a
// closed one is replaced by /dev/null opened the other way round (standard output and error read-only,
// standard input write-only), so that using it fails (EBADF) and is reported, instead of reading or
// writing some other file.
void guard_standard_descriptors();

}  // namespace boxcyl::cli
