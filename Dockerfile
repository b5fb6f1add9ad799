# Every lab live in a browser, from a container: for machines with no
# OpenGL 4.3 window (macOS, Windows, Codespaces). Mesa's llvmpipe renders
# offscreen inside the container and `lab serve` shows the lab on a page.
# The steps are the project's own set-up script, the same one the README's
# two commands run on a fresh Debian machine. As docs/running.md runs it (macOS,
# Windows or Codespaces):
#
#   docker build -t gl-labs .
#   docker run --rm -it -p 127.0.0.1:8080:8080 -v "$PWD:/labs" -e LAB=pipeline gl-labs
#
# then open http://localhost:8080/. The second command builds the mounted
# tree (only what changed since the last run) before it serves, so that an
# edit shows after Ctrl-C and the same command again.
#
# The image holds `lab` and `course` only (the container preset's targets:
# no test suite, no benchmarks), and the compiler cache of that build. The
# mount hides the image's own build-container/, but the mounted tree sits at
# the same path, so its first build takes every unchanged file's object from
# the cache: the first frame comes within a minute of `docker run`, not after
# a build of everything. setup.sh builds both without the caller's locale
# (ccache keys objects by it: docs/performance.md, The container's first
# build). The same image runs `course grade-class --shard` (docs/cluster/).
FROM debian:bookworm

COPY . /labs
WORKDIR /labs
# build-container/ (LAB_PRESET=container), so that a tree mounted from the
# host keeps its own build/ apart.
ENV LAB_PRESET=container
ENV CCACHE_DIR=/var/cache/gl-labs-ccache
RUN bash scripts/setup.sh && rm -rf /var/lib/apt/lists/* && ccache --show-stats | head -n 3

EXPOSE 8080
ENV LAB=pipeline
# In a container the page is reached from outside it: listen on every
# interface (docker run -p 127.0.0.1:8080:8080 keeps it to the host itself).
CMD ["bash", "-c", "bash scripts/setup.sh >/dev/null && exec build-container/bin/lab serve \"$LAB\" --host 0.0.0.0 --port 8080"]
