#pragma once

#include "field_renderer.hpp"

namespace grass_qt {

class GlFieldRenderer final : public FieldRenderer {
public:
    using FieldRenderer::FieldRenderer;
    ~GlFieldRenderer() override;

protected:
    bool create_context(const grass_context_desc& desc, QString* error) override;
    grass_result draw(QString* error) override;
    void clear_host_errors() override;
};

} // namespace grass_qt
