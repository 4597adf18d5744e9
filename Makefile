# The two commands: `make serve` and `make test`. Everything else supports them.
BUILD   ?= build
JOBS    ?= 2
PORT    ?= 8080
CMAKE_FLAGS ?=

.PHONY: gallery test-openapi deps build serve test test-asan fuzz bench-build bench lighting bench-accuracy loadtest loadtest-admission loadtest-cache test-proxy test-docker test-repeat test-browser test-deploy test-cluster test-memory clean

deps:
	@scripts/install-deps

# Configure every time (a no-op when nothing changed) so a tree configured with other options is corrected.
build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DRASTERD_BUILD_TESTS=ON -DRASTERD_BUILD_SERVER=ON $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD) -j$(JOBS) -- --no-print-directory

serve: build
	@$(BUILD)/rasterd serve --port $(PORT)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

# The whole suite under AddressSanitizer + UndefinedBehaviorSanitizer, in its own build tree.
test-asan:
	@$(MAKE) --no-print-directory test BUILD=build-asan CMAKE_FLAGS="-DRASTERD_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo"

# Each libFuzzer target for FUZZ_SECONDS (default 600), seeded from examples/ and fuzz/corpus/.
# Findings land in fuzz-out/; each one becomes a regression test.
FUZZ_SECONDS ?= 600
FUZZ_TARGETS ?= scene_fuzzer obj_fuzzer texture_fuzzer stl_fuzzer ply_fuzzer gltf_fuzzer 3mf_fuzzer
# The model readers also start from the real files of Debian's assimp-testmodels (read there, not copied).
ASSIMP_MODELS := /usr/share/assimp/models
FUZZ_SEEDS_stl_fuzzer := $(ASSIMP_MODELS)/STL
FUZZ_SEEDS_ply_fuzzer := $(ASSIMP_MODELS)/PLY
FUZZ_SEEDS_gltf_fuzzer := $(ASSIMP_MODELS)/glTF2 $(ASSIMP_MODELS)/glTF
FUZZ_SEEDS_3mf_fuzzer := $(ASSIMP_MODELS)/3MF
fuzz:
	@scripts/install-deps fuzz
	@CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRASTERD_BUILD_FUZZ=ON \
	  -DRASTERD_BUILD_TESTS=OFF -DRASTERD_BUILD_SERVER=OFF >/dev/null
	@cmake --build build-fuzz -j$(JOBS) -- --no-print-directory
	@for t in $(FUZZ_TARGETS); do \
	  mkdir -p fuzz-out/$$t/corpus; \
	  echo "== $$t for $(FUZZ_SECONDS) s"; \
	  build-fuzz/fuzz/$$t -max_total_time=$(FUZZ_SECONDS) -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
	    -artifact_prefix=fuzz-out/$$t/ -print_final_stats=1 $$( [ -f fuzz/$${t%_fuzzer}.dict ] && echo -dict=fuzz/$${t%_fuzzer}.dict ) fuzz-out/$$t/corpus fuzz/corpus/$$t \
	    $$(case $$t in stl_fuzzer) echo $(FUZZ_SEEDS_stl_fuzzer);; ply_fuzzer) echo $(FUZZ_SEEDS_ply_fuzzer);; gltf_fuzzer) echo $(FUZZ_SEEDS_gltf_fuzzer);; 3mf_fuzzer) echo $(FUZZ_SEEDS_3mf_fuzzer);; esac) || exit 1; \
	done

bench-build: build
	@scripts/install-deps bench
	@cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DRASTERD_BUILD_BENCH=ON -DRASTERD_BUILD_TESTS=OFF \
	  -DBLEND2D_DIR="$(BLEND2D_DIR)" >/dev/null
	@cmake --build build-bench -j$(JOBS) -- --no-print-directory

# Measures the default light and rewrites docs/lighting.md.
lighting: bench-build
	@scripts/lighting

# Measures and rewrites docs/performance.md (BENCH_RUNS=11 by default).
bench: bench-build
	@scripts/bench

# Error against an exact reference and render time for every anti-aliasing level; rewrites
# docs/accuracy.md and docs/accuracy.png. BLEND2D_DIR=<a built Blend2D checkout> adds Blend2D's rows.
BLEND2D_DIR ?=
bench-accuracy: bench-build
	@build-bench/bench/accuracy .
	@build-bench/bench/model_defaults .

# wrk against a local server on the mid-size scene; LOADTEST_SECONDS=30 by default.
loadtest: bench-build
	@scripts/loadtest

# A web page's mix under 16 and 256 connections, old and new admission side by side; writes docs/admission.md
# (ADMISSION_SECONDS=20 a row).
loadtest-admission: build
	@scripts/install-deps load
	@scripts/loadtest-admission

# One image URL over and over: rendering, the 304, rasterd's cheapest request and nginx's cache hit, side by
# side (LOADTEST_SECONDS=10 a row); writes docs/cache.txt. Why rasterd has no cache of its own.
loadtest-cache: build
	@scripts/loadtest-cache

# examples/nginx.conf in front of rasterd, checked (installs nginx).
test-proxy: build
	@scripts/test-proxy

# The suite REPEAT times (default 20) under make test and make test-asan, with stress-ng loading every
# core unless STRESS=0: no verdict may depend on machine speed.
REPEAT ?= 20
STRESS ?= 1
test-repeat:
	@REPEAT=$(REPEAT) STRESS=$(STRESS) scripts/test-repeat

# Builds the Dockerfile and checks the image: runtime libraries, HEALTHCHECK, renders identical to
# $(BUILD)/rasterd's, non-root, clean SIGTERM, and test-memory's phases against the image under the manifest's
# limits (TEST_DOCKER_MEMORY=0 skips those); prints its size. docker where an engine runs, else podman.
test-docker: build
	@BUILD=$(BUILD) scripts/test-docker

# The playground (GET /) in headless Chromium: every example's pixels equal the CLI's, errors shown on
# their line, OBJ uploads, copy as curl; rewrites docs/images/playground.png. Installs chromium (heavy).
test-browser: build
	@scripts/install-deps browser
	@/usr/bin/python3 scripts/test-browser --binary $(BUILD)/rasterd --screenshot docs/images/playground.png

# deploy/: every Kubernetes manifest and compose.yaml parsed and checked, the nginx config through nginx -t.
test-deploy:
	@scripts/install-deps cluster
	@/usr/bin/python3 scripts/test-deploy

# Three replicas behind deploy/nginx.conf on loopback under wrk while one is stopped and one killed; rewrites
# docs/scaling.md (CLUSTER_SECONDS=20 by default).
test-cluster: build
	@scripts/install-deps cluster
	@BUILD=$(BUILD) scripts/test-cluster

# Issue 39's finding 1: rasterd serve in a 2 GiB memory cgroup (made here; needs root) with the manifest's
# settings, sent two 33 MB face-dense OBJs at once, then 48 sphere OBJs, then 48 face-dense: only 200s, 503s
# with Retry-After and 413/422s, no lost connection, no OOM kill. Rewrites docs/memory.md's measured section.
# RASTERD_BINARY=path tests another binary; MEMORY_IMAGE=image runs the same against containers of an image
# under the manifest's limits (make test-docker does, on the image it builds) and rewrites the image section.
test-memory: build
	@BUILD=$(BUILD) scripts/test-memory

# Every model of Debian's assimp-testmodels that rasterd reads, rendered with the defaults a bare model gets,
# as one contact sheet per format: rewrites docs/gallery.md and docs/images/gallery-*.png; fails on a crash.
gallery: build
	@scripts/install-deps gallery
	@scripts/gallery --binary $(BUILD)/rasterd

# openapi.json against the OpenAPI 3.1 schema, fetched from the npm registry (not kept in the repository).
test-openapi: build
	@BUILD=$(BUILD) scripts/test-openapi

clean:
	rm -rf build build-asan build-bench build-fuzz fuzz-out
