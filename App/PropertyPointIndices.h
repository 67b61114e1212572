// SPDX-License-Identifier: LGPL-2.1-or-later
// A list of small integers per point (region, patch, label) that is saved as a binary file in
// the .FCStd archive, as App::PropertyFloatList is, instead of one XML element per value: a
// million points then cost 4 MB on disk and a fraction of a second to reopen.
#pragma once

#include <App/PropertyStandard.h>

namespace FeatureLines {

class PropertyPointIndices : public App::PropertyIntegerList
{
    TYPESYSTEM_HEADER_WITH_OVERRIDE();

public:
    void Save(Base::Writer& writer) const override;
    void Restore(Base::XMLReader& reader) override;
    void SaveDocFile(Base::Writer& writer) const override;
    void RestoreDocFile(Base::Reader& reader) override;
    App::Property* Copy() const override;
};

} // namespace FeatureLines
