#include "garden/export/part_export.h"

#include "garden/app/garden_session.h"
#include "garden/export/hyperfun_export.h"

namespace hg::garden {

std::string extractPart(GardenSession& session, const std::string& from, const std::string& model,
                        const std::string& name) {
    const int i = session.findSculpture(from);
    if (i < 0) return "no sculpture named '" + from + "'";
    if (session.sculptures()[static_cast<std::size_t>(i)].gridOnly())
        return std::string("a part of ") + (session.sculptures()[static_cast<std::size_t>(i)].meshed() ? "a mesh" : "a scanned volume") +
               " cannot be made a sculpture yet: its program would have to read the "
               "grid, which HyperFun cannot; the selection still keeps every tool inside it";
    std::string why;
    const auto mask = session.modelMask(model, why);
    if (!mask) return why;
    const HyperFunExport text = exportHyperFunPart(session, i, *mask);
    if (!text.error.empty()) return text.error;
    const auto a = session.partFromText(i, name, text.text, *mask, "extract of '" + from + "' by model '" + model + "'");
    return a.action ? session.apply(*a.action) : a.why;
}

}  // namespace hg::garden
