# The experiments of the thesis as make rules (make experiments runs
# this file; make -f mk/experiments.mk works alone after make all).
#
# An experiment ID (scripts/exp-ID.sh) writes RES/ID/summary.md.  It
# depends on RES/.stamps/ID, the checksums of everything the script may
# read: itself, explib.sh, the programs it names, the matrices, the map
# and the mode (scripts/experiments.sh --stamp ID).  The stamp is
# rewritten only when that content changes, so touch or cp -p of an input
# reruns nothing, and a changed input reruns the experiments that read
# it, whose own cache (explib.sh's cached) then recomputes only the steps
# that depend on it.  The experiments in TIMING measure time: they hold
# an exclusive lock, the others a shared one, so that whatever
# -j says a timing experiment never runs beside another.
#
#   make experiments [ONLY=fig6.3,tab6.1] [QUICK=0] [-j2]
#   RES (results), BIN (bin), ENVMAP, FRS_MATRIX, FRS_MATRIX3, JOBS,
#   SSHLOGIN and SSH are passed to the scripts (scripts/explib.sh).

RES ?= results
BIN ?= $(CURDIR)/bin
MODE ?= $(if $(filter 0,$(QUICK)),full,quick)
export RES BIN MODE ENVMAP FRS_MATRIX FRS_MATRIX3 JOBS SSHLOGIN SSH

ALL := $(patsubst scripts/exp-%.sh,%,$(wildcard scripts/exp-*.sh))
SEL := $(if $(ONLY),$(shell sh scripts/experiments.sh --select '$(ONLY)'),$(ALL))
# the experiments that time programs (frs(7) lists what each measures)
TIMING := 3d fig6.13-tab6.2 fig6.14-tab6.3 fig6.15 mc vac
LOCK = $(RES)/.lock

.PHONY: experiments FORCE
.DELETE_ON_ERROR:
.SECONDARY:

experiments: $(SEL:%=$(RES)/%/summary.md)
	@sh scripts/report.sh
	@echo "experiments: $(words $(SEL)) up to date ($(MODE) mode); see $(RES)/REPORT.md" >&2

ifeq ($(SEL),)
$(error experiments: no experiment matches ONLY=$(ONLY))
endif

$(RES)/.stamps/%: FORCE
	@mkdir -p $(@D)
	@sh scripts/experiments.sh --stamp $* >$@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv -f $@.tmp $@; fi

$(RES)/%/summary.md: $(RES)/.stamps/%
	@mkdir -p $(RES)
	@flock $(if $(filter $*,$(TIMING)),-x,-s) $(LOCK) sh scripts/exp-$*.sh

FORCE:
