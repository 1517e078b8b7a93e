# frs: Forced Random Sampling toolchain.  GNU make.
#
#   make            build the programs into bin/
#   make check      install missing packages, build with sanitizers, run
#                   every test (last line: "N passed, N failed")
#   make demo       install missing packages, build, run the pipeline,
#                   pictures in results/
#   make bench      benchmarks of the make build (and -march=native beside)
#   make fuzz       libFuzzer on every parser (mk/fuzz.mk)
#   make install    PREFIX=/usr/local DESTDIR= (also BINDIR LIBDIR INCDIR
#                   MANDIR PKGCONFIGDIR): programs, frs.h, libfrs.a,
#                   libfrs.so, frs.pc, frs-static.pc, the shipped data,
#                   man pages; make uninstall

PREFIX ?= /usr/local
BINDIR ?= $(PREFIX)/bin
LIBDIR ?= $(PREFIX)/lib
INCDIR ?= $(PREFIX)/include
MANDIR ?= $(PREFIX)/share/man
DESTDIR ?=

CC ?= cc
CXX ?= c++
PKG_CONFIG ?= pkg-config
# -O3: the samplers' loops vectorise (HSW's descent, the writer's check).
# On x86-64 the functions marked FRS_WIDE (src/lib/base/wide.h) also have
# AVX2 and AVX-512 clones picked at run time; 256-bit vectors in the
# latter, as GCC tunes for the processors that have it (512 were slower).
HOST_ARCH := $(shell uname -m)
OPT ?= -O3 -g $(if $(filter x86_64 amd64,$(HOST_ARCH)),-mprefer-vector-width=256)
WARN = -Wall -Wextra -Wshadow -Wconversion -Werror=implicit-function-declaration
CSTD = -std=c11

# Recursive (=) so that a sub-make started after scripts/deps.sh sees the
# packages it installed.
# -isystem: warnings in the libraries' headers are not ours.
PKG_CFLAGS = $(patsubst -I%,-isystem %,$(shell $(PKG_CONFIG) --cflags \
	libpng OpenEXR OpenCL 2>/dev/null))
# OpenEXR: the C core, plus the C++ library for the DWAA/DWAB codecs that
# the 3.1 core lacks (src/lib/maps/exrcxx.cc).
PKG_LIBS = $(shell $(PKG_CONFIG) --libs libpng OpenEXR OpenCL 2>/dev/null) \
	-lstdc++
CMOCKA_LIBS = $(shell $(PKG_CONFIG) --libs cmocka 2>/dev/null || echo -lcmocka)

PROGS = imap frd-gen frd-prep frs-sample pts-render ref-sample hsw-sample \
	discrepancy dda mc-error
# A program's home is src/P/: its main P.c and the work only it does (the
# rest of src/P/*.c, an archive of its own, $(B)/obj/P/own.a, which the
# tests link too).
own = $(filter-out src/$(1)/$(1).c,$(wildcard src/$(1)/*.c))
OWNPROGS = $(foreach p,$(PROGS),$(if $(call own,$(p)),$(p)))
# The library by stage (README, Layout): base, maps, formats, sample,
# api; each includes only from its own folder and those before.
LIBSRC = $(wildcard src/lib/*/*.c)
LIBCXXSRC = $(wildcard src/lib/*/*.cc)
# The programs' shared work, not in libfrs ($(B)/libfrscli.a): option
# handling and messages, the output step and its atomic files, the point
# files and sets, the --sets writer, the statistics over groups of sets,
# rasters, the reference samplers, the FFT, float formatting.
CLISRC = $(wildcard src/cli/*.c)
TESTSRC = $(wildcard test/test_*.c)
# test/hard/: the numerical hard cases gathered in one suite.
HARDSRC = $(wildcard test/hard/test_*.c)
# The benchmarks' reference implementations (test/ref/) and drivers
# (test/bench/), built as $(B)/test/NAME beside the tests.
REFSRC = $(wildcard test/ref/*.c) $(wildcard test/bench/*.c)
REFNAMES = $(notdir $(REFSRC:.c=))
# Programs on the public API alone, as a user writes them (test/user_*.c).
USERSRC = $(wildcard test/user_*.c)

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

# Where the programs and the library find the shipped data (the default
# matrices, sunset.exr; src/lib/base/datadir.c): $FRS_DATA, else share/frs
# beside libfrs.so and beside the program, wherever they were installed,
# then SRCDATA (the source tree, for uninstalled builds; SRCDATA= for
# binaries that name no build directory) and $(PREFIX)/share/frs.  They
# are written to $(B)/gen/paths.h, which changes only when they do: make
# install PREFIX=... recompiles the one object that reads it.
SRCDATA ?= $(CURDIR)/data
# src/lib/frs.h is the public header (libfrs(3)); the rest is included by
# folder, "base/err.h", "cli/cli.h".
ALL_CFLAGS = $(CSTD) $(WARN) $(VFLAGS) -Isrc/lib -Isrc -I$(B)/gen $(PKG_CFLAGS) \
	$(CFLAGS) -MMD -MP
ALL_LDFLAGS = $(VFLAGS) $(LDFLAGS)
LIBS = $(PKG_LIBS) -lm -lpthread

CLSRC = $(wildcard cl/*.cl)
LIBOBJ = $(LIBSRC:src/lib/%.c=$(B)/lib/%.o) \
	$(LIBCXXSRC:src/lib/%.cc=$(B)/lib/%.o) $(B)/gen/clsrc.o
PROGBIN = $(PROGS:%=$(B)/bin/%)
PROGMAIN = $(foreach p,$(PROGS),$(B)/obj/$(p)/$(p).o)
OWNAR = $(OWNPROGS:%=$(B)/obj/%/own.a)
OWNOBJ = $(foreach p,$(OWNPROGS),\
	$(patsubst src/%.c,$(B)/obj/%.o,$(call own,$(p))))
TESTBIN = $(TESTSRC:test/%.c=$(B)/test/%) $(HARDSRC:test/hard/%.c=$(B)/test/%)
REFBIN = $(REFNAMES:%=$(B)/test/%)
USERBIN = $(USERSRC:test/%.c=$(B)/test/%)

.PHONY: all progs libs tests check demo bench install uninstall clean deps \
	lint-man experiments FORCE
.DELETE_ON_ERROR:
.SECONDARY:

all: progs
ifeq ($(VARIANT),rel)
all: libs
	@mkdir -p bin
	@for p in $(PROGS); do cmp -s $(B)/bin/$$p bin/$$p || \
	    { cp -f $(B)/bin/$$p bin/$$p.tmp && mv -f bin/$$p.tmp bin/$$p; }; done
endif

progs: $(PROGBIN)
tests: $(TESTBIN) $(PROGBIN) $(REFBIN) $(USERBIN)

# -ffp-contract=off: g++ fuses a * b + c by default (gcc in C11 mode does
# not), so imap_luma inlined here gave other EXR maps under -march=native.
ALL_CXXFLAGS = -std=c++14 -ffp-contract=off -Wall -Wextra $(VFLAGS) \
	-Isrc/lib -Isrc $(PKG_CFLAGS) $(CXXFLAGS) -MMD -MP

# The one compile rule: $(call objects,OBJDIR,SRCDIR,FLAGS) makes
# OBJDIR/X.o from SRCDIR/X.c (or X.cc, by $(CXX)) with the flags above
# and FLAGS; the table below (and mk/fuzz.mk) says which folder goes where.
define objects
$(1)/%.o: $(2)/%.c
	@mkdir -p $$(@D)
	$$(CC) $$(ALL_CFLAGS) $(3) -c $$< -o $$@
$(1)/%.o: $(2)/%.cc
	@mkdir -p $$(@D)
	$$(CXX) $$(ALL_CXXFLAGS) $(3) -c $$< -o $$@
endef

# The library with its embedded kernels ($(B)/gen) twice: for libfrs.a,
# and position-independent for libfrs.so (below); the programs' helpers;
# the programs (src/P/ into $(B)/obj/P/); the tests (test/hard/ includes
# test/'s helpers), the benchmark drivers and the references.
$(eval $(call objects,$(B)/lib,src/lib))
$(eval $(call objects,$(B)/gen,$(B)/gen))
$(eval $(call objects,$(B)/pic/lib,src/lib,-fPIC))
$(eval $(call objects,$(B)/pic/gen,$(B)/gen,-fPIC))
$(eval $(call objects,$(B)/cli,src/cli))
$(eval $(call objects,$(B)/obj,src))
$(eval $(call objects,$(B)/test,test,-Wno-conversion))
$(eval $(call objects,$(B)/test,test/hard,-Itest -Wno-conversion))
$(eval $(call objects,$(B)/test,test/bench,-Wno-conversion))
$(eval $(call objects,$(B)/test,test/ref,-Wno-conversion))

$(B)/libfrs.a: $(LIBOBJ)
	@mkdir -p $(@D)
	rm -f $@ && $(AR) rcs $@ $^

CLIOBJ = $(CLISRC:src/cli/%.c=$(B)/cli/%.o)
$(B)/libfrscli.a: $(CLIOBJ)
	@mkdir -p $(@D)
	rm -f $@ && $(AR) rcs $@ $^

$(B)/gen/paths.h: FORCE
	@mkdir -p $(@D)
	@printf '#define FRS_SRCDATA "%s"\n#define FRS_SHAREDIR "%s"\n' \
	    '$(SRCDATA)' '$(PREFIX)/share/frs' >$@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv -f $@.tmp $@; fi
$(B)/lib/base/datadir.o $(B)/pic/lib/base/datadir.o: $(B)/gen/paths.h

# The OpenCL kernels, embedded so that installed programs need no source
# tree.
$(B)/gen/clsrc.c: $(CLSRC) scripts/cl2c.sh
	@mkdir -p $(@D)
	sh scripts/cl2c.sh $@ $(CLSRC)

# The dynamic library libfrs.so (make libs; part of make all in the rel
# variant): the library's sources again as position-independent objects
# in $(B)/pic/, exporting only the API of src/lib/frs.h (the version
# script src/lib/libfrs.map).  The programs and tests link libfrs.a, which keeps
# the internal symbols they use.
SOMAJOR = 2
SONAME = libfrs.so.$(SOMAJOR)
SOMINOR = 2
SOFILE = libfrs.so.$(SOMAJOR).$(SOMINOR).0
PICOBJ = $(LIBOBJ:$(B)/%=$(B)/pic/%)
SOMAP = src/lib/libfrs.map

libs: $(B)/libfrs.a $(B)/$(SOFILE) $(B)/$(SONAME) $(B)/libfrs.so

# -z defs: every symbol the library uses must come from $(LIBS).
$(B)/$(SOFILE): $(PICOBJ) $(SOMAP)
	$(CC) -shared -Wl,-soname,$(SONAME) -Wl,--version-script=$(SOMAP) \
	    -Wl,-z,defs $(ALL_LDFLAGS) $(PICOBJ) $(LIBS) -o $@

$(B)/$(SONAME) $(B)/libfrs.so: $(B)/$(SOFILE)
	ln -sf $(SOFILE) $@

# What the programs link: their own archive (when they have one), the
# helpers and libfrs, in that order (the helpers call the library's
# internals: errors, memory, files, number formatting); the tests,
# benchmarks and fuzz drivers every program's own archive too
# (test/user_*.c: libfrs alone, as a user has it).
PROGLIBS = $(B)/libfrscli.a $(B)/libfrs.a
TESTLIBS = $(OWNAR) $(PROGLIBS)
LINK = $(CC) $(ALL_LDFLAGS) $(filter %.o,$^) $(filter %.a,$^) $(LIBS)

$(B)/obj/%/own.a:
	rm -f $@ && $(AR) rcs $@ $^
define program
$(B)/bin/$(1): $(B)/obj/$(1)/$(1).o \
    $(if $(call own,$(1)),$(B)/obj/$(1)/own.a) $(PROGLIBS)
	@mkdir -p $$(@D)
	$$(LINK) -o $$@
$(B)/obj/$(1)/own.a: $(patsubst src/%.c,$(B)/obj/%.o,$(call own,$(1)))
endef
$(foreach p,$(PROGS),$(eval $(call program,$(p))))

$(B)/test/test_%: $(B)/test/test_%.o $(TESTLIBS)
	$(LINK) $(CMOCKA_LIBS) -o $@

$(REFBIN): $(B)/test/%: $(B)/test/%.o $(TESTLIBS)
	$(LINK) -o $@

$(B)/test/user_%: $(B)/test/user_%.o $(B)/libfrs.a
	$(CC) $(ALL_LDFLAGS) $< $(B)/libfrs.a $(LIBS) -o $@

-include $(LIBOBJ:.o=.d) $(CLIOBJ:.o=.d) $(PROGMAIN:.o=.d) $(OWNOBJ:.o=.d) \
	$(TESTBIN:=.d) $(REFBIN:=.d) $(USERBIN:=.d) $(PICOBJ:.o=.d)

deps:
	@sh scripts/deps.sh

# The test build is a sub-make so that it sees packages deps just added.
check: deps
	@$(MAKE) --no-print-directory VARIANT=san tests
	@sh test/run.sh build/san

demo: deps
	@$(MAKE) --no-print-directory all
	@sh scripts/demo.sh

# The benchmarks time the build make install installs (build/rel); the
# -march=native build beside it is for scripts/bench-build.sh's comparison.
bench: deps
	@$(MAKE) --no-print-directory all $(REFNAMES:%=build/rel/test/%)
	@$(MAKE) --no-print-directory VARIANT=bench progs
	@sh scripts/bench.sh build/rel

# make experiments [ONLY=fig6.3,tab6.1] [QUICK=0] [-j2]: every thesis
# experiment (scripts/exp-*.sh), results and results/REPORT.md; the rules
# are mk/experiments.mk (only what changed is recomputed).
experiments: deps
	@$(MAKE) --no-print-directory all
	@$(MAKE) --no-print-directory -f mk/experiments.mk experiments

lint-man:
	mandoc -Tlint -Wwarning man/man*/*.[0-9]

# frs.pc and frs-static.pc (libfrs.a): src/lib/*.pc.in with the install
# paths, libdir and includedir
# written relative to ${prefix} where they lie under it (so that
# pkg-config --define-prefix can move them).
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
VERSION := $(shell sed -n 's/^\#define FRS_VERSION "\(.*\)"$$/\1/p' \
	src/lib/api/version.h)
PCSUBST = -e 's|@PREFIX@|$(PREFIX)|g' \
	-e 's|@LIBDIR@|$(patsubst $(PREFIX)/%,$${prefix}/%,$(LIBDIR))|g' \
	-e 's|@INCDIR@|$(patsubst $(PREFIX)/%,$${prefix}/%,$(INCDIR))|g' \
	-e 's|@VERSION@|$(VERSION)|g'
INSTLIB = $(DESTDIR)$(LIBDIR)

# From $(B), not bin/: make VARIANT=rel B=DIR install needs no other build.
install: progs libs
	mkdir -p $(DESTDIR)$(BINDIR) $(DESTDIR)$(INCDIR) $(INSTLIB) \
	    $(DESTDIR)$(PKGCONFIGDIR) $(DESTDIR)$(PREFIX)/share/frs
	for p in $(PROGS); do \
	    install -m 755 $(B)/bin/$$p $(DESTDIR)$(BINDIR)/ || exit 1; done
	install -m 644 data/default.frd data/default3.frd data/sunset.exr \
	    $(DESTDIR)$(PREFIX)/share/frs/
	install -m 644 src/lib/frs.h $(DESTDIR)$(INCDIR)/
	install -m 644 $(B)/libfrs.a $(INSTLIB)/
	install -m 755 $(B)/$(SOFILE) $(INSTLIB)/
	ln -sf $(SOFILE) $(INSTLIB)/$(SONAME)
	ln -sf $(SOFILE) $(INSTLIB)/libfrs.so
	sed $(PCSUBST) src/lib/frs.pc.in >$(DESTDIR)$(PKGCONFIGDIR)/frs.pc
	sed $(PCSUBST) src/lib/frs-static.pc.in \
	    >$(DESTDIR)$(PKGCONFIGDIR)/frs-static.pc
	for s in 1 3 5 7; do mkdir -p $(DESTDIR)$(MANDIR)/man$$s && \
	    for f in man/man$$s/*.$$s; do [ ! -f "$$f" ] || \
	    install -m 644 "$$f" $(DESTDIR)$(MANDIR)/man$$s/ || exit 1; \
	    done; done

uninstall:
	for p in $(PROGS); do rm -f $(DESTDIR)$(BINDIR)/$$p; done
	rm -f $(DESTDIR)$(PREFIX)/share/frs/default.frd \
	    $(DESTDIR)$(PREFIX)/share/frs/default3.frd \
	    $(DESTDIR)$(PREFIX)/share/frs/sunset.exr
	rm -f $(DESTDIR)$(INCDIR)/frs.h $(INSTLIB)/libfrs.a \
	    $(INSTLIB)/$(SOFILE) $(INSTLIB)/$(SONAME) $(INSTLIB)/libfrs.so \
	    $(DESTDIR)$(PKGCONFIGDIR)/frs.pc \
	    $(DESTDIR)$(PKGCONFIGDIR)/frs-static.pc
	for s in 1 3 5 7; do for f in man/man$$s/*.$$s; do \
	    rm -f $(DESTDIR)$(MANDIR)/man$$s/$${f##*/}; done; done

clean:
	rm -rf build bin

# make fuzz, make fuzz-build and the replay drivers of make tests.
include mk/fuzz.mk
