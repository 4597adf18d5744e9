# The two commands: `make serve` and `make test`. Everything else supports them.
BUILD   ?= build
JOBS    ?= 2
PORT    ?= 8080
CMAKE_FLAGS ?=

.PHONY: deps build serve test test-asan clean

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

clean:
	rm -rf build build-asan
