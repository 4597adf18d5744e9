# Build stage: the same install script and make target as on a developer machine.
FROM debian:bookworm AS build
WORKDIR /src
COPY scripts/install-deps scripts/install-deps
RUN scripts/install-deps
COPY . .
RUN make build BUILD=/build

# Runtime: only the shared libraries rasterd links against (from `ldd build/rasterd` mapped to packages with
# dpkg -S; their own dependencies, such as brotli, come with them), curl for the health check, and a
# non-root user. zlib (image URLs) and libcrypto (ETags) are rasterd's own links too, listed although
# libcpp-httplib0.11 brings them: the image is the same.
FROM debian:bookworm-slim
RUN apt-get update -qq \
 && apt-get install -y -qq --no-install-recommends libcpp-httplib0.11 libisal2 libtinyobjloader2rc10 zlib1g libssl3 curl ca-certificates \
 && rm -rf /var/lib/apt/lists/* \
 && useradd --system --no-create-home --uid 10001 rasterd
COPY --from=build /build/rasterd /usr/local/bin/rasterd
USER rasterd
EXPOSE 8080
ENV PORT=8080
HEALTHCHECK --interval=10s --timeout=2s --retries=3 CMD curl -fsS http://127.0.0.1:${PORT}/healthz || exit 1
# rasterd handles SIGTERM itself (sigwait thread), so it can run as PID 1 directly.
ENTRYPOINT ["/usr/local/bin/rasterd"]
CMD ["serve"]
