// SPDX-License-Identifier: Apache-2.0
// Where a frame is drawn: a multisampled offscreen framebuffer, resolved for reading back
// (PNG, video) and for showing in a window. The window and --headless draw the same way.
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <vector>

namespace viewer {

class Canvas {
public:
    Canvas() = default;
    ~Canvas();
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;

    // (Re)makes the buffers when the size changes; samples per pixel 1 to 8 (a software
    // renderer pays for each). False with the reason.
    bool resize(int width, int height, int samples, std::string& error);
    void bind() const;  // draw into it
    // Resolves the samples; then pixels can be read or shown.
    void resolve() const;
    // Copies the resolved image to the window's back buffer (the current context's framebuffer 0).
    void present(int window_framebuffer_width, int window_framebuffer_height) const;
    // The resolved image as RGB rows from the top.
    void read_rgb(std::vector<unsigned char>& rgb) const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    void release();
    int width_ = 0, height_ = 0, samples_ = 0;
    GLuint multisampled_ = 0, colour_samples_ = 0, depth_samples_ = 0;
    GLuint resolved_ = 0, colour_ = 0;
};

// Samples per pixel for the current context: 4, or 1 on a software renderer (llvmpipe,
// softpipe), where multisampling costs as much as the scene.
int default_samples();

// Writes RGB rows from the top as a PNG (stb_image_write). False with the reason.
bool write_png(const std::string& path, int width, int height, const std::vector<unsigned char>& rgb,
               std::string& error);

// Pipes frames to an ffmpeg process: H.264 for .mp4, a palette-optimised GIF for .gif.
class VideoEncoder {
public:
    ~VideoEncoder();
    bool open(const std::string& path, int width, int height, double fps, std::string& error);
    bool write(const std::vector<unsigned char>& rgb, std::string& error);
    // Waits for ffmpeg; false if it failed.
    bool close(std::string& error);
    bool is_open() const { return pid_ > 0; }

private:
    int pid_ = -1;
    int pipe_ = -1;
    std::string path_;
};

}  // namespace viewer
