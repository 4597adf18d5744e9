# Build stage: what the image ships and nothing else. The same install script as on a developer machine,
# without the test-only packages (gtest, assimp-testmodels, python3-jsonschema, curl), and only the rasterd
# target, without the tests (make build compiles those too: half the objects).
FROM debian:bookworm AS build
WORKDIR /src
COPY scripts/install-deps scripts/install-deps
RUN scripts/install-deps build-only
COPY . .
RUN cmake -S . -B /build -DCMAKE_BUILD_TYPE=Release -DRASTERD_BUILD_TESTS=OFF -DRASTERD_BUILD_SERVER=ON >/dev/null \
 && cmake --build /build -j"$(nproc)" --target rasterd

# Runtime: only the shared libraries rasterd links against (from `ldd build/rasterd` mapped to packages with
# dpkg -S; their own dependencies, such as brotli, come with them) and a non-root user. zlib (image URLs) and
# libcrypto (ETags) are rasterd's own links too, listed although libcpp-httplib0.11 brings them: the image is
# the same. No curl: the health check is rasterd's own (`rasterd healthcheck`).
FROM debian:bookworm-slim
RUN apt-get update -qq \
 && apt-get install -y -qq --no-install-recommends libcpp-httplib0.11 libisal2 libtinyobjloader2rc10 libexpat1 zlib1g libssl3 \
 && rm -rf /var/lib/apt/lists/* \
 && groupadd --system -g 10001 rasterd \
 && useradd --system --no-create-home -u 10001 -g 10001 rasterd
COPY --from=build /build/rasterd /usr/local/bin/rasterd
# Numeric, so that Kubernetes' runAsNonRoot can verify it without the image's /etc/passwd; equal to
# deploy/kubernetes/deployment.yaml's runAsUser:runAsGroup (scripts/test-deploy checks both).
USER 10001:10001
EXPOSE 8080
ENV PORT=8080
# `rasterd healthcheck` asks PID 1 (the server) on the port and host it was given: its --port/--host flags,
# else RASTERD_PORT, PORT and RASTERD_HOST in its environment; so `IMAGE serve --port 9000` is checked on 9000.
# Its own timeouts are 2 s, within the 3 s here, so a slow answer is reported in its words, not killed.
HEALTHCHECK --interval=10s --timeout=3s --retries=3 CMD ["/usr/local/bin/rasterd", "healthcheck"]
# rasterd handles SIGTERM itself (sigwait thread), so it can run as PID 1 directly.
ENTRYPOINT ["/usr/local/bin/rasterd"]
CMD ["serve"]
