# frs: Forced Random Sampling toolchain.  GNU make.
#
#   make            build the programs into bin/
#   make check      install missing packages, build with sanitizers, run
#                   every test (last line: "N passed, N failed")
#   make demo       install missing packages, build, run the pipeline,
#                   pictures in results/
#   make bench      benchmarks, built with -O3 -march=native
#   make install    PREFIX=/usr/local DESTDIR= MANDIR=$(PREFIX)/share/man

PREFIX ?= /usr/local
BINDIR ?= $(PREFIX)/bin
LIBDIR ?= $(PREFIX)/lib
INCDIR ?= $(PREFIX)/include
MANDIR ?= $(PREFIX)/share/man
DESTDIR ?=

CC ?= cc
CXX ?= c++
PKG_CONFIG ?= pkg-config
OPT ?= -O2 -g
WARN = -Wall -Wextra -Wshadow -Wconversion
CSTD = -std=c11

# Recursive (=) so that a sub-make started after scripts/deps.sh sees the
# packages it installed.
# -isystem: warnings in the libraries' headers are not ours.
PKG_CFLAGS = $(patsubst -I%,-isystem %,$(shell $(PKG_CONFIG) --cflags \
	libpng OpenEXR OpenCL 2>/dev/null))
# OpenEXR: the C core, plus the C++ library for the DWAA/DWAB codecs that
# the 3.1 core lacks (src/lib/exrcxx.cc).
PKG_LIBS = $(shell $(PKG_CONFIG) --libs libpng OpenEXR OpenCL 2>/dev/null) \
	-lstdc++
CMOCKA_LIBS = $(shell $(PKG_CONFIG) --libs cmocka 2>/dev/null || echo -lcmocka)

PROGS = imap frd-gen frd-prep frs-sample pts-render ref-sample hsw-sample \
	discrepancy dda
LIBSRC = $(wildcard src/lib/*.c)
LIBCXXSRC = $(wildcard src/lib/*.cc)
TESTSRC = $(wildcard test/test_*.c)
REFSRC = $(wildcard test/ref_*.c)

# Variant: rel (bin/, portable), san (sanitizers, for make check),
# bench (-O3 -march=native, for make bench).
VARIANT ?= rel
B = build/$(VARIANT)
ifeq ($(VARIANT),san)
VFLAGS = -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer \
	-fno-sanitize-recover=undefined
else ifeq ($(VARIANT),bench)
VFLAGS = -O3 -march=native -g
else
VFLAGS = $(OPT)
endif

# Where frs-sample finds the default matrix: the source tree, then the
# installed copy.
PATHS = -DFRS_SRCDATA='"$(CURDIR)/data"' -DFRS_SHAREDIR='"$(PREFIX)/share/frs"'
ALL_CFLAGS = $(CSTD) $(WARN) $(VFLAGS) -Isrc/lib $(PKG_CFLAGS) $(PATHS) \
	$(CFLAGS) -MMD -MP
ALL_LDFLAGS = $(VFLAGS) $(LDFLAGS)
LIBS = $(PKG_LIBS) -lm -lpthread

CLSRC = $(wildcard cl/*.cl)
LIBOBJ = $(LIBSRC:src/lib/%.c=$(B)/lib/%.o) \
	$(LIBCXXSRC:src/lib/%.cc=$(B)/lib/%.o) $(B)/gen/clsrc.o
PROGBIN = $(PROGS:%=$(B)/bin/%)
TESTBIN = $(TESTSRC:test/%.c=$(B)/test/%)
REFBIN = $(REFSRC:test/%.c=$(B)/test/%)

.PHONY: all progs tests check demo bench install uninstall clean deps \
	lint-man experiments
.DELETE_ON_ERROR:
.SECONDARY:

all: progs
ifeq ($(VARIANT),rel)
	@mkdir -p bin
	@for p in $(PROGS); do cp -f $(B)/bin/$$p bin/$$p.tmp && \
	    mv -f bin/$$p.tmp bin/$$p; done
endif

progs: $(PROGBIN)
tests: $(TESTBIN) $(PROGBIN) $(REFBIN)

$(B)/libfrs.a: $(LIBOBJ)
	@mkdir -p $(@D)
	rm -f $@ && $(AR) rcs $@ $^

$(B)/lib/%.o: src/lib/%.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

# The OpenCL kernels, embedded so that installed programs need no source
# tree.
$(B)/gen/clsrc.c: $(CLSRC) scripts/cl2c.sh
	@mkdir -p $(@D)
	sh scripts/cl2c.sh $@ $(CLSRC)

$(B)/gen/clsrc.o: $(B)/gen/clsrc.c
	$(CC) $(CSTD) $(VFLAGS) $(CFLAGS) -c $< -o $@

$(B)/lib/%.o: src/lib/%.cc
	@mkdir -p $(@D)
	$(CXX) -std=c++14 -Wall -Wextra $(VFLAGS) -Isrc/lib $(PKG_CFLAGS) \
	    $(CXXFLAGS) -MMD -MP -c $< -o $@

$(B)/obj/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

$(B)/bin/%: $(B)/obj/%.o $(B)/libfrs.a
	@mkdir -p $(@D)
	$(CC) $(ALL_LDFLAGS) $< $(B)/libfrs.a $(LIBS) -o $@

$(B)/test/%.o: test/%.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -Wno-conversion -c $< -o $@

$(B)/test/test_%: $(B)/test/test_%.o $(B)/libfrs.a
	$(CC) $(ALL_LDFLAGS) $< $(B)/libfrs.a $(LIBS) $(CMOCKA_LIBS) -o $@

# Reference implementations for the benchmarks (test/ref_*.c).
$(B)/test/ref_%: $(B)/test/ref_%.o $(B)/libfrs.a
	$(CC) $(ALL_LDFLAGS) $< $(B)/libfrs.a $(LIBS) -o $@

-include $(LIBOBJ:.o=.d) $(PROGS:%=$(B)/obj/%.d) $(TESTBIN:=.d) $(REFBIN:=.d)

deps:
	@sh scripts/deps.sh

# The test build is a sub-make so that it sees packages deps just added.
check: deps
	@$(MAKE) --no-print-directory VARIANT=san tests
	@sh test/run.sh build/san

demo: deps
	@$(MAKE) --no-print-directory all
	@sh scripts/demo.sh

bench: deps
	@$(MAKE) --no-print-directory VARIANT=bench progs $(REFSRC:test/%.c=build/bench/test/%)
	@sh scripts/bench.sh build/bench

# make experiments [ONLY=fig6.3,tab6.1] [QUICK=0]: every thesis experiment
# (scripts/exp-*.sh), results and results/REPORT.md.
experiments: deps
	@$(MAKE) --no-print-directory all
	@ONLY='$(ONLY)' QUICK='$(QUICK)' sh scripts/experiments.sh

lint-man:
	mandoc -Tlint -Wwarning man/man*/*.[0-9]

install: all
	mkdir -p $(DESTDIR)$(BINDIR) $(DESTDIR)$(MANDIR)/man1 \
	    $(DESTDIR)$(MANDIR)/man5 $(DESTDIR)$(MANDIR)/man7
	for p in $(PROGS); do install -m 755 bin/$$p $(DESTDIR)$(BINDIR)/; done
	mkdir -p $(DESTDIR)$(PREFIX)/share/frs
	install -m 644 data/default.frd $(DESTDIR)$(PREFIX)/share/frs/
	for s in 1 3 5 7; do for f in man/man$$s/*.$$s; do \
	    [ -f "$$f" ] && install -m 644 "$$f" $(DESTDIR)$(MANDIR)/man$$s/; \
	    done; done; true

uninstall:
	for p in $(PROGS); do rm -f $(DESTDIR)$(BINDIR)/$$p; done
	rm -f $(DESTDIR)$(PREFIX)/share/frs/default.frd
	for s in 1 3 5 7; do for f in man/man$$s/*.$$s; do \
	    rm -f $(DESTDIR)$(MANDIR)/man$$s/$${f##*/}; done; done

clean:
	rm -rf build bin
