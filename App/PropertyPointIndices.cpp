// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "PropertyPointIndices.h"

#include <Base/Exception.h>
#include <Base/Reader.h>
#include <Base/Stream.h>
#include <Base/Writer.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

using namespace FeatureLines;

TYPESYSTEM_SOURCE(FeatureLines::PropertyPointIndices, App::PropertyIntegerList)

void PropertyPointIndices::Save(Base::Writer& writer) const
{
    if (writer.isForceXML()) { // undo/redo and copy/paste write everything inline
        writer.Stream() << writer.ind() << "<PointIndices count=\"" << getSize() << "\">\n";
        writer.incInd();
        for (long v : getValues()) {
            writer.Stream() << writer.ind() << "<I v=\"" << v << "\"/>\n";
        }
        writer.decInd();
        writer.Stream() << writer.ind() << "</PointIndices>\n";
    } else {
        writer.Stream() << writer.ind() << "<PointIndices file=\""
                        << (getSize() ? writer.addFile(getName(), this) : std::string())
                        << "\"/>\n";
    }
}

void PropertyPointIndices::Restore(Base::XMLReader& reader)
{
    reader.readElement("PointIndices");
    if (reader.hasAttribute("file")) {
        const std::string file(reader.getAttribute("file"));
        if (file.empty()) {
            setValues(std::vector<long>());
        } else {
            reader.addFile(file.c_str(), this);
        }
        return;
    }
    const long count = reader.getAttributeAsInteger("count");
    std::vector<long> values(static_cast<size_t>(std::max(0L, count)));
    for (long& v : values) {
        reader.readElement("I");
        v = reader.getAttributeAsInteger("v");
    }
    reader.readEndElement("PointIndices");
    setValues(values);
}

void PropertyPointIndices::SaveDocFile(Base::Writer& writer) const
{
    Base::OutputStream out(writer.Stream());
    out << static_cast<std::uint32_t>(getSize());
    for (long v : getValues()) {
        out << static_cast<std::int32_t>(v);
    }
}

void PropertyPointIndices::RestoreDocFile(Base::Reader& reader)
{
    // A damaged file may end early or state any count: values are read while the file has
    // them (no allocation from the stated count alone), and a short file restores nothing.
    // FreeCAD reports the exception as "Reading failed from embedded file"; the empty list then
    // disagrees with the others and the object says so (StoredResult.h).
    setValues(std::vector<long>());
    Base::InputStream in(reader);
    std::uint32_t count = 0;
    in >> count;
    std::vector<long> values;
    values.reserve(std::min<std::uint32_t>(count, 1u << 20));
    while (in && values.size() < count) {
        std::int32_t value = 0;
        in >> value;
        if (!in) {
            break;
        }
        values.push_back(value);
    }
    if (values.size() != count) {
        throw Base::FileException(("'" + std::string(getName()) + "' holds " +
                                   std::to_string(values.size()) + " of its " +
                                   std::to_string(count) + " values")
                                      .c_str());
    }
    setValues(values);
}

App::Property* PropertyPointIndices::Copy() const
{
    auto* p = new PropertyPointIndices();
    p->setValues(getValues());
    return p;
}
