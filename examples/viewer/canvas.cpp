// SPDX-License-Identifier: Apache-2.0
#include "canvas.h"

#include <stb_image_write.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace viewer {

Canvas::~Canvas() { release(); }

void Canvas::release() {
    if (multisampled_ == 0) return;
    glDeleteFramebuffers(1, &multisampled_);
    glDeleteFramebuffers(1, &resolved_);
    glDeleteRenderbuffers(1, &colour_samples_);
    glDeleteRenderbuffers(1, &depth_samples_);
    glDeleteRenderbuffers(1, &colour_);
    multisampled_ = resolved_ = colour_samples_ = depth_samples_ = colour_ = 0;
}

int default_samples() {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const bool software = renderer != nullptr && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe"));
    return software ? 1 : 4;
}

bool Canvas::resize(int width, int height, int samples, std::string& error) {
    if (width == width_ && height == height_ && samples == samples_ && multisampled_ != 0) return true;
    release();
    width_ = width;
    height_ = height;
    samples_ = samples;
    const int stored = samples > 1 ? samples : 0;  // 0: an ordinary buffer, not one of 1 sample
    glGenRenderbuffers(1, &colour_samples_);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_samples_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, stored, GL_RGBA8, width, height);
    glGenRenderbuffers(1, &depth_samples_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_samples_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, stored, GL_DEPTH_COMPONENT24, width, height);
    glGenFramebuffers(1, &multisampled_);
    glBindFramebuffer(GL_FRAMEBUFFER, multisampled_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_samples_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_samples_);
    const GLenum multisampled_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glGenRenderbuffers(1, &colour_);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glGenFramebuffers(1, &resolved_);
    glBindFramebuffer(GL_FRAMEBUFFER, resolved_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    const GLenum resolved_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (multisampled_status != GL_FRAMEBUFFER_COMPLETE || resolved_status != GL_FRAMEBUFFER_COMPLETE) {
        error = "the offscreen framebuffer is incomplete (" + std::to_string(width) + " x " + std::to_string(height) +
                ", " + std::to_string(samples) + " samples)";
        release();
        return false;
    }
    return true;
}

void Canvas::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, multisampled_);
    glViewport(0, 0, width_, height_);
}

void Canvas::resolve() const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void Canvas::present(int window_framebuffer_width, int window_framebuffer_height) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, window_framebuffer_width, window_framebuffer_height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Canvas::read_rgb(std::vector<unsigned char>& rgb) const {
    const std::size_t row = 3 * static_cast<std::size_t>(width_);
    std::vector<unsigned char> bottom_up(row * static_cast<std::size_t>(height_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data());
    rgb.resize(bottom_up.size());
    for (int y = 0; y < height_; ++y)
        std::memcpy(&rgb[row * static_cast<std::size_t>(y)], &bottom_up[row * static_cast<std::size_t>(height_ - 1 - y)],
                    row);
}

bool write_png(const std::string& path, int width, int height, const std::vector<unsigned char>& rgb,
               std::string& error) {
    if (stbi_write_png(path.c_str(), width, height, 3, rgb.data(), 3 * width) == 0) {
        error = "cannot write " + path;
        return false;
    }
    return true;
}

VideoEncoder::~VideoEncoder() {
    std::string ignored;
    close(ignored);
}

bool VideoEncoder::open(const std::string& path, int width, int height, double fps, std::string& error) {
    const bool gif = path.size() >= 4 && path.compare(path.size() - 4, 4, ".gif") == 0;
    const bool mp4 = path.size() >= 4 && path.compare(path.size() - 4, 4, ".mp4") == 0;
    if (!gif && !mp4) {
        error = "--video wants a .mp4 or .gif file, got " + path;
        return false;
    }
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    const std::string rate = std::to_string(fps);
    // GIF: one palette for the whole clip, then dithering against it, redrawing only what
    // changed. MP4: H.264 at a size any player takes (even dimensions, yuv420p).
    const std::string filter =
        gif ? "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer:bayer_scale=4:diff_mode=rectangle"
            : "crop=trunc(iw/2)*2:trunc(ih/2)*2";
    std::vector<std::string> arguments = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo",
                                          "-pix_fmt", "rgb24", "-s", size, "-r", rate, "-i", "-", "-vf", filter};
    if (mp4) arguments.insert(arguments.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "20", "-movflags", "+faststart"});
    if (gif) arguments.insert(arguments.end(), {"-loop", "0"});
    arguments.push_back(path);
    std::vector<char*> argv;
    for (std::string& a : arguments) argv.push_back(a.data());
    argv.push_back(nullptr);

    int fds[2];
    if (pipe(fds) != 0) {
        error = std::string("pipe: ") + std::strerror(errno);
        return false;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    pid_t pid = -1;
    const int spawned = posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    if (spawned != 0) {
        ::close(fds[1]);
        error = std::string("cannot run ffmpeg (apt-get install ffmpeg): ") + std::strerror(spawned);
        return false;
    }
    std::signal(SIGPIPE, SIG_IGN);  // a failed ffmpeg shows as a write error, not a dead viewer
    pid_ = pid;
    pipe_ = fds[1];
    path_ = path;
    return true;
}

bool VideoEncoder::write(const std::vector<unsigned char>& rgb, std::string& error) {
    std::size_t written = 0;
    while (written < rgb.size()) {
        const ssize_t n = ::write(pipe_, rgb.data() + written, rgb.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error = "ffmpeg stopped taking frames for " + path_;
            return false;
        }
        written += static_cast<std::size_t>(n);
    }
    return true;
}

bool VideoEncoder::close(std::string& error) {
    if (pid_ <= 0) return true;
    ::close(pipe_);
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    pipe_ = -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        error = "ffmpeg failed to write " + path_;
        return false;
    }
    return true;
}

}  // namespace viewer
