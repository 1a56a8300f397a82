-- Pandoc filter for scripts/render-docs: links between the pages point to the rendered pages
-- (NAME.md -> NAME.html, anchors kept); other relative links, except figures/ (copied beside
-- the pages), point back to the source tree through the metadata field source_prefix (the
-- path from the rendered page's folder to the source page's folder).

local source_prefix = ""

local function is_relative(target)
  return not target:match("^%a[%w+.-]*:") and not target:match("^/") and not target:match("^#")
end

local function rewrite(target)
  if not is_relative(target) then
    return target
  end
  local path, anchor = target:match("^([^#]*)(.*)$")
  if path:match("%.md$") then
    return path:gsub("%.md$", ".html") .. anchor
  end
  if path:match("^figures/") then
    return target
  end
  return source_prefix .. target
end

function Meta(meta)
  if meta.source_prefix then
    source_prefix = pandoc.utils.stringify(meta.source_prefix)
  end
end

function Link(link)
  link.target = rewrite(link.target)
  return link
end

function Image(image)
  image.src = rewrite(image.src)
  return image
end

return {{Meta = Meta}, {Link = Link, Image = Image}}
