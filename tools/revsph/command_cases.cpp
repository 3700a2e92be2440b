#include "core/case_keys.hpp"
#include "core/model_registry.hpp"
#include "tools/revsph/commands.hpp"

#include <iostream>
#include <sstream>

namespace revsph::cli {

namespace {

std::string allowed_values(const KeyDecl& key, std::string_view quote) {
  std::string text;
  for (const std::string& value : key.allowed) {
    text +=
        (text.empty() ? "" : ", ") + std::string(quote) + "\"" + value + "\"" + std::string(quote);
  }
  return text;
}

// `text` in lines of at most `width` characters, each after `indent`.
void print_wrapped(std::ostream& out, const std::string& text, std::size_t indent,
                   std::size_t width) {
  std::istringstream words(text);
  std::string word;
  std::size_t column = 0;
  while (words >> word) {
    if (column > 0 && column + 1 + word.size() > width) {
      out << "\n";
      column = 0;
    }
    out << (column == 0 ? std::string(indent, ' ') : std::string(" ")) << word;
    column += (column == 0 ? indent : 1) + word.size();
  }
  out << "\n";
}

void print_text(std::ostream& out, const KeyTable& table, const std::string& title) {
  out << title << ":\n";
  for (const KeyDecl& key : table.keys()) {
    out << "  " << key.path << "  (" << to_string(key.type)
        << (key.unit == "-" ? std::string() : ", " + key.unit) << "; "
        << (key.default_value.starts_with("required") ? key.default_value
                                                      : "default: " + key.default_value)
        << ")\n";
    std::string meaning = key.meaning;
    if (!key.allowed.empty()) {
      meaning += ". One of " + allowed_values(key, "") + ".";
    }
    print_wrapped(out, meaning, 6, 96);
  }
}

// Markdown table cells: a '|' would end the cell.
std::string cell(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    escaped += c == '|' ? std::string("\\|") : std::string(1, c);
  }
  return escaped;
}

void print_markdown(std::ostream& out, const KeyTable& table, const std::string& title) {
  out << "\n## " << title << "\n\n";
  out << "| key | type | unit | default | meaning |\n|---|---|---|---|---|\n";
  for (const KeyDecl& key : table.keys()) {
    std::string meaning = key.meaning;
    if (!key.allowed.empty()) {
      meaning += ". One of " + allowed_values(key, "`") + ".";
    }
    out << "| `" << key.path << "` | " << to_string(key.type) << " | " << cell(key.unit) << " | "
        << cell(key.default_value) << " | " << cell(meaning) << " |\n";
  }
}

int print_keys(const std::string& model, bool markdown) {
  std::vector<const ModelEntry*> models;
  for (const ModelEntry& entry : model_registry().entries()) {
    if (model == "all" || entry.name == model) {
      models.push_back(&entry);
    }
  }
  if (models.empty()) {
    std::string known;
    for (const ModelEntry& entry : model_registry().entries()) {
      known += ", " + entry.name;
    }
    print_error("no model \"" + model + "\" (models: all" + known + ")");
    return bad_input;
  }
  std::ostream& out = std::cout;
  if (markdown) {
    out << "# Case-file keys\n\n"
           "Every key a case file may have, generated from the key tables that the case "
           "readers check each read against (`core/case_keys.hpp`), so nothing read is missing "
           "here. Do not edit: regenerate with\n\n"
           "    build/bin/revsph cases --keys all --markdown > docs/case-keys.md\n\n"
           "(the test `CaseKeysDoc.CommittedReferenceIsWhatTheBinaryPrints` fails while this file "
           "differs from that output).\n\n"
           "`particles[].min` is the key `min` of every `[[particles]]` block. Unit `1`: "
           "dimensionless; `-`: no unit. A default in quotes or digits is the value taken "
           "when the key is absent; `required`: the case is refused without it.\n";
    print_markdown(out, common_case_keys(), "Every model");
  } else {
    out << "Keys of a case file (" << (model == "all" ? "every model" : "model " + model)
        << "); particles[].KEY is KEY in every [[particles]] block. As Markdown: "
           "revsph cases --keys "
        << model << " --markdown\n\n";
    print_text(out, common_case_keys(), "every model");
  }
  for (const ModelEntry* entry : models) {
    const std::string title = "model " + entry->name + ": " + entry->description;
    if (entry->keys == nullptr) {
      print_error("model " + entry->name + " has no key table");
      return simulation_failed;
    }
    if (markdown) {
      print_markdown(out, entry->keys(),
                     "`model = \"" + entry->name + "\"`: " + entry->description);
    } else {
      out << "\n";
      print_text(out, entry->keys(), title);
    }
  }
  return success;
}

} // namespace

int cases_command(const std::string& name, const std::string& keys_model, bool markdown) {
  if (!keys_model.empty()) {
    return print_keys(keys_model, markdown);
  }
  if (!name.empty()) {
    const BuiltinCase* builtin = find_builtin_case(name);
    if (builtin == nullptr) {
      print_error("no built-in case \"" + name + "\" (list them with: revsph cases)");
      return bad_input;
    }
    std::cout << builtin->text;
    return success;
  }
  std::cout << "built-in cases (use the name where a CASE.toml is expected; print one with "
               "`revsph cases NAME`; every key of a model's case files: `revsph cases --keys "
               "MODEL`):\n";
  for (const BuiltinCase& c : builtin_cases()) {
    std::cout << "  " << c.name << "  (model " << c.model << ")\n";
  }
  std::cout << "models:\n";
  for (const ModelEntry& model : model_registry().entries()) {
    std::cout << "  " << model.name << "  " << model.description << "\n";
  }
  return success;
}

} // namespace revsph::cli
