// write_hdf5_tables through deal.II's HDF5 wrapper.
#include "commands/hdf5_tables.h"

#include "base/atomic_file.h"
#include "base/number.h"

#include <deal.II/base/hdf5.h>

namespace gearfem::commands
{
  std::string dataset_name(const std::string &header)
  {
    std::string out;
    for (const char c : header)
      out += c == '/' ? std::string(" per ") : std::string(1, c);
    return out;
  }

  void write_hdf5_tables(const std::vector<std::pair<std::string, Table>> &tables,
                         const std::filesystem::path &file,
                         const std::map<std::string, std::string> &attributes)
  {
    TemporaryPath tmp(file);
    {
      dealii::HDF5::File f(tmp.path().string(), dealii::HDF5::File::FileAccessMode::create);
      for (const auto &[k, v] : attributes)
        f.set_attribute(k, v);
      for (const auto &[name, table] : tables)
        {
          if (table.n_rows() == 0)
            continue;
          auto g = f.create_group(name);
          for (std::size_t c = 0; c < table.n_columns(); ++c)
            {
              std::vector<double> col(table.n_rows());
              for (std::size_t i = 0; i < table.n_rows(); ++i)
                {
                  col[i] = table.row(i)[c];
                  require_finite_output(col[i], file.string(),
                                        "dataset '" + name + "/" + table.headers()[c] + "'");
                }
              g.write_dataset(dataset_name(table.headers()[c]), col);
            }
        }
    }
    tmp.commit();
  }
} // namespace gearfem::commands
