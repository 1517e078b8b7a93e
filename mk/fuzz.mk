# Fuzzing (test/fuzz/): one libFuzzer target per parser; included by the
# Makefile, whose compile rule (objects) and link recipe (LINK) it uses.
#   make fuzz [FUZZ_SECONDS=600] [-j2]   build with clang and run each
#       target on its seed corpus (new inputs in build/fuzz/corpus/T/),
#       crashes saved in $(FUZZ_CRASHES)/T/
#   make fuzz-build                      only build them, build/fuzz/fuzz_T
# make tests also builds replay drivers, $(B)/fuzz/replay_T, that run
# the same targets on the seed corpus and the saved crashes (test/run.sh).
FUZZ_TARGETS = $(patsubst test/fuzz/fuzz_%.c,%,$(wildcard test/fuzz/fuzz_*.c))
FUZZ_SECONDS ?= 600
FUZZ_CC ?= clang
FUZZ_CXX ?= clang++
FUZZ_SAN = -fsanitize=address,undefined -fno-sanitize-recover=undefined
FUZZ_VFLAGS = -O1 -g -fno-omit-frame-pointer $(FUZZ_SAN) \
	-fsanitize=fuzzer-no-link
FUZZ_CRASHES ?= test/fuzz/crashes
FUZZ_FLAGS ?= -rss_limit_mb=4096 -timeout=30
FUZZBIN = $(FUZZ_TARGETS:%=build/fuzz/fuzz_%)
REPLAYBIN = $(FUZZ_TARGETS:%=$(B)/fuzz/replay_%)

.PHONY: fuzz fuzz-build $(FUZZ_TARGETS:%=fuzz-%)

tests: $(REPLAYBIN)

# The drivers; fuzz_opts runs every program's main: the programs' mains
# again (src/P/P.c), main renamed main_P (dashes as underscores), with
# their own archives.
$(eval $(call objects,$(B)/fuzz,test/fuzz))
$(eval $(call objects,$(B)/fuzz/prog,src,\
	-Dmain=main_$$(subst -,_,$$(notdir $$*))))
FUZZMAIN = $(foreach p,$(PROGS),fuzz/prog/$(p)/$(p).o)

$(B)/fuzz/replay_%: $(B)/fuzz/fuzz_%.o $(B)/fuzz/replay.o $(TESTLIBS)
	$(LINK) -o $@
$(B)/fuzz/replay_opts: $(FUZZMAIN:%=$(B)/%)

-include $(wildcard $(B)/fuzz/*.d $(B)/fuzz/prog/*/*.d)

# The fuzz variant: the library and the drivers again, built by clang
# with the fuzzer's instrumentation into build/fuzz/ (its drivers in
# build/fuzz/fuzz/, as every variant's), linked with libFuzzer.
fuzz-build:
	@$(MAKE) --no-print-directory VARIANT=fuzz CC=$(FUZZ_CC) \
	    CXX=$(FUZZ_CXX) VFLAGS='$(FUZZ_VFLAGS)' $(FUZZBIN)

build/fuzz/fuzz_%: build/fuzz/fuzz/fuzz_%.o \
    $(OWNPROGS:%=build/fuzz/obj/%/own.a) build/fuzz/libfrscli.a \
    build/fuzz/libfrs.a
	$(FUZZ_CXX) -fsanitize=fuzzer $(FUZZ_SAN) $(filter %.o,$^) \
	    $(filter %.a,$^) $(LIBS) -o $@
build/fuzz/fuzz_opts: $(FUZZMAIN:%=build/fuzz/%)

fuzz: $(FUZZ_TARGETS:%=fuzz-%)

$(FUZZ_TARGETS:%=fuzz-%): fuzz-%: fuzz-build
	@mkdir -p build/fuzz/corpus/$* $(FUZZ_CRASHES)/$*
	build/fuzz/fuzz_$* -max_total_time=$(FUZZ_SECONDS) $(FUZZ_FLAGS) \
	    -artifact_prefix=$(FUZZ_CRASHES)/$*/ \
	    build/fuzz/corpus/$* test/fuzz/corpus/$*
