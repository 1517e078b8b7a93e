// OpenEXR through the C++ library, for what the C core of OpenEXR 3.1
// cannot decode: its OpenEXRCore has no DWAA/DWAB decompressor ("not yet
// implemented in C"), and lossy DWA is what real HDR maps use.  Channels
// are still read one by one as float planes and matched by name.
// Only exrio.c calls this, through the C function at the end.

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <Iex.h>

#include <cstdint>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

extern "C" {
#include "maps/imap.h"
#include "base/err.h"
#include "maps/exrcxx.h"
}

namespace {

// An input stream over a buffer in memory (files and standard input are
// read whole before decoding).
class MemStream : public OPENEXR_IMF_NAMESPACE::IStream {
public:
	MemStream(const unsigned char *buf, size_t len, const char *name)
	    : IStream(name), buf_(buf), len_(len), pos_(0) {}

	bool read(char c[], int n) override
	{
		if (n < 0 || static_cast<size_t>(n) > len_ - pos_)
			throw IEX_NAMESPACE::InputExc("unexpected end of file");
		std::memcpy(c, buf_ + pos_, static_cast<size_t>(n));
		pos_ += static_cast<size_t>(n);
		return pos_ < len_;
	}
	uint64_t tellg() override { return pos_; }
	void seekg(uint64_t pos) override
	{
		pos_ = pos > len_ ? len_ : static_cast<size_t>(pos);
	}

private:
	const unsigned char *buf_;
	size_t len_, pos_;
};

int read_planes(OPENEXR_IMF_NAMESPACE::InputFile &file, const char *name,
    struct frs_imap *m)
{
	using namespace OPENEXR_IMF_NAMESPACE;
	const ChannelList &ch = file.header().channels();
	const IMATH_NAMESPACE::Box2i dw = file.header().dataWindow();
	const int64_t w = int64_t(dw.max.x) - dw.min.x + 1;
	const int64_t h = int64_t(dw.max.y) - dw.min.y + 1;
	const bool lum = ch.findChannel("Y") != nullptr;
	const char *names[3] = { "R", "G", "B" };
	int nplanes = lum ? 1 : 3;

	if (!lum && (!ch.findChannel("R") || !ch.findChannel("G") ||
	    !ch.findChannel("B"))) {
		std::string have;
		for (ChannelList::ConstIterator i = ch.begin(); i != ch.end(); ++i)
			have += (have.empty() ? "" : ", ") + std::string(i.name());
		return frs_fail("%s: no usable channel (need Y or R, G, B; file "
		    "has %s)", name, have.c_str());
	}
	if (w <= 0 || h <= 0 || w > FRS_MAP_MAX_SIDE || h > FRS_MAP_MAX_SIDE)
		return frs_fail("%s: impossible data window %lldx%lld", name,
		    (long long)w, (long long)h);
	if (imap_alloc(m, uint32_t(w), uint32_t(h)) < 0)
		return frs_fail_context(name);
	std::vector<float> planes(size_t(nplanes) * size_t(w) * size_t(h));
	FrameBuffer fb;
	for (int k = 0; k < nplanes; k++) {
		// Slices are addressed by absolute pixel coordinates.
		char *base = reinterpret_cast<char *>(planes.data() +
		    size_t(k) * size_t(w) * size_t(h)) -
		    (int64_t(dw.min.x) + int64_t(dw.min.y) * w) *
		    int64_t(sizeof(float));
		fb.insert(lum ? "Y" : names[k], Slice(FLOAT, base,
		    sizeof(float), sizeof(float) * size_t(w)));
	}
	file.setFrameBuffer(fb);
	file.readPixels(dw.min.y, dw.max.y);
	size_t n = size_t(w) * size_t(h);
	for (size_t i = 0; i < n; i++)
		m->v[i] = lum ? planes[i] : imap_luma(planes[i], planes[n + i],
		    planes[2 * n + i]);
	return 0;
}

} // namespace

extern "C" int exr_cxx_read(const unsigned char *buf, size_t len,
    const char *name, struct frs_imap *m)
{
	std::memset(m, 0, sizeof *m);
	try {
		MemStream in(buf, len, name);
		OPENEXR_IMF_NAMESPACE::InputFile file(in, 1);
		int rc = read_planes(file, name, m);
		if (rc < 0)
			imap_free(m);
		return rc;
	} catch (const std::exception &e) {
		imap_free(m);
		return frs_fail("%s: cannot decode: %s", name, e.what());
	}
}
